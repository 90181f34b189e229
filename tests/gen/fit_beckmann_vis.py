#!/usr/bin/env python3
"""Fits appear__erfcx (appear.h, Beckmann visible-normal sampler):
erfcx(a) = exp(a^2) erfc(a) = t R(t), t = 1/(1 + a/2), a in [0, 10]
(t in [1/6, 1]), R a polynomial of degree 8, minimax for the relative
error (discrete Remez of fit_special.py; reference erfcx from mpmath at 30
digits). Prints the coefficients, lowest degree first, as float literals;
appear.h evaluates them by Horner from the highest. The float error of the
sampler is measured by tests/test_microfacet.c (suite sampling_accuracy).
Run: python3 tests/gen/fit_beckmann_vis.py (needs numpy and mpmath)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fit_special import remez, mono, show
import mpmath as mp

mp.mp.dps = 30

def erfcx(a):
    return float(mp.erfc(a) * mp.exp(a * a))

if __name__ == '__main__':
    f = lambda t: erfcx(2 * (1 / t - 1)) / t          # R(t), a = 2 (1/t - 1)
    c, m = remez(f, lambda t: 1.0 / f(t), [mono(j) for j in range(9)], 1 / 6, 1.0, n_grid=20001, iters=40)
    show('erfcx(a) = t R(t), t = 1/(1 + a/2), a in [0, 10], R deg 8, rel', c, m)

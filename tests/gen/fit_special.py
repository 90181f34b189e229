#!/usr/bin/env python3
"""Fits the minimax polynomials of appear.h's special functions (section
"Special functions"). Discrete Remez exchange on a dense grid in double
(numpy), weighted so that the fitted error is the relative (or absolute)
error of the final float function. Run: python3 tests/fit_special.py
The coefficients printed are pasted into appear.h as float literals; the
float error of the result is measured by tests/test_special.c, not here."""
import numpy as np
from math import erf, erfc, pi, log, atan, sqrt, exp

def remez(f, w, basis, a, b, n_grid=200001, iters=40):
    """min over c of max_x |w(x) (f(x) - sum c_k basis_k(x))| on [a,b]."""
    x = np.linspace(a, b, n_grid)
    # avoid exact endpoints where f/basis may be singular (handled by caller)
    F = np.array([f(t) for t in x]); W = np.array([w(t) for t in x])
    B = np.array([[bk(t) for bk in basis] for t in x])
    n = len(basis)
    # start: Chebyshev-distributed reference
    idx = np.round((1 - np.cos(np.linspace(0, pi, n + 1))) / 2 * (n_grid - 1)).astype(int)
    best = None
    for it in range(iters):
        A = np.zeros((n + 1, n + 1))
        A[:, :n] = B[idx]
        A[:, n] = [(-1) ** i / W[j] for i, j in enumerate(idx)]
        sol = np.linalg.solve(A, F[idx])
        c, E = sol[:n], sol[n]
        err = W * (F - B @ c)
        m = np.max(np.abs(err))
        if best is None or m < best[1]:
            best = (c.copy(), m)
        # new reference: alternating extrema
        s = np.sign(err); s[s == 0] = 1
        cand = []
        start = 0
        for i in range(1, n_grid + 1):
            if i == n_grid or s[i] != s[start]:
                seg = np.arange(start, i)
                cand.append(seg[np.argmax(np.abs(err[seg]))])
                start = i
        cand = np.array(cand)
        while len(cand) > n + 1:
            # drop the smallest, keeping alternation (drop at ends or merge)
            k = np.argmin(np.abs(err[cand]))
            cand = np.delete(cand, k)
            # re-merge equal-sign neighbours
            keep = [cand[0]]
            for j in cand[1:]:
                if np.sign(err[j]) == np.sign(err[keep[-1]]):
                    if abs(err[j]) > abs(err[keep[-1]]): keep[-1] = j
                else:
                    keep.append(j)
            cand = np.array(keep)
        if len(cand) < n + 1:
            break
        idx = cand
        if abs(m - abs(E)) < 1e-3 * m:
            break
    return best

def show(name, c, m):
    print(name, 'max weighted err %.3e' % m)
    print('   ', ', '.join('%.9ef' % float(np.float32(v)) for v in c))

def mono(k): return lambda t, k=k: t ** k

if __name__ == '__main__':
    # sin(r) = r + r^3 (s1 + s2 r^2 + s3 r^4), r in [0, pi/4], relative error
    c, m = remez(lambda r: (np.sin(r) - r) / r ** 3 if r > 1e-4 else -1/6 + r*r/120,
                 lambda r: r ** 2 if r > 1e-4 else 1e-8, [mono(2 * k) for k in range(3)], 1e-6, pi / 4)
    show('sin deg7 (r^3 * P(r^2)), weight r^2 ~ rel', c, m)
    # cos(r) = 1 - r^2/2 + r^4 (c1 + c2 r^2 + c3 r^4), absolute
    c, m = remez(lambda r: (np.cos(r) - 1 + r * r / 2) / r ** 4 if r > 1e-3 else 1/24 - r*r/720,
                 lambda r: r ** 4, [mono(2 * k) for k in range(3)], 1e-6, pi / 4)
    show('cos deg8 (1 - r^2/2 + r^4 P(r^2)), abs', c, m)
    # exp(r) = 1 + r + r^2 P(r), r in [-ln2/2, ln2/2], relative
    L = log(2) / 2
    c, m = remez(lambda r: (exp(r) - 1 - r) / r ** 2 if abs(r) > 1e-4 else 0.5 + r / 6,
                 lambda r: r * r / exp(r), [mono(k) for k in range(5)], -L, L)
    show('exp: 1 + r + r^2 P4(r), rel', c, m)
    # log(1+f) = 2 atanh(s), s = f/(2+f), |s| <= 3-2sqrt2; atanh(s) = s + s^3 P(s^2)
    S = 3 - 2 * sqrt(2)
    c, m = remez(lambda s: (np.arctanh(s) - s) / s ** 3 if s > 1e-4 else 1/3 + s*s/5,
                 lambda s: s ** 2, [mono(2 * k) for k in range(3)], 1e-6, S)
    show('log: 2(s + s^3 P(s^2)), rel', c, m)
    # atan(t) = t + t^3 P(t^2), t in [0,1], absolute (and relative near 0)
    c, m = remez(lambda t: (atan(t) - t) / t ** 3 if t > 1e-4 else -1/3 + t*t/5,
                 lambda t: t ** 3 / max(atan(t), 1e-30) if t > 0 else 0.0,
                 [mono(2 * k) for k in range(7)], 1e-6, 1.0)
    show('atan: t + t^3 P6(t^2), rel', c, m)
    # erf small: erf(x) = x (a0 + x^2 P(x^2)), |x| <= 1, relative
    c, m = remez(lambda x: erf(x) / x if x > 1e-6 else 2/sqrt(pi),
                 lambda x: 1.0, [mono(2 * k) for k in range(6)], 1e-6, 1.0)
    show('erf small: x P5(x^2), rel (|x|<=1)', c, m)
    # erfc(x) = t exp(-x^2 + P(t)), t = 1/(1 + x/2), x in [0.75, 10.1], relative
    def g(x):
        from mpmath import erfc as merfc, mpf, log as mlog
        t = 1 / (1 + x / 2)
        return float(mlog(merfc(mpf(x))) + mpf(x) ** 2 - mlog(t))
    xs = np.linspace(0.75, 10.1, 4001)
    gs = np.array([g(v) for v in xs])
    from numpy.polynomial import polynomial as P
    tmap = 1 / (1 + xs / 2)
    # discrete Remez on precomputed samples (in t)
    def remez_samples(T, F, deg, iters=60):
        n = deg + 1; N = len(T)
        idx = np.round(np.linspace(0, N - 1, n + 1)).astype(int)
        B = np.vander(T, n, increasing=True)
        best = None
        for it in range(iters):
            A = np.zeros((n + 1, n + 1)); A[:, :n] = B[idx]; A[:, n] = [(-1) ** i for i in range(n + 1)]
            sol = np.linalg.solve(A, F[idx]); cc = sol[:n]
            err = F - B @ cc; m = np.max(np.abs(err))
            if best is None or m < best[1]: best = (cc.copy(), m)
            s = np.sign(err); cand = []; start = 0
            for i in range(1, N + 1):
                if i == N or s[i] != s[start]:
                    seg = np.arange(start, i); cand.append(seg[np.argmax(np.abs(err[seg]))]); start = i
            cand = list(cand)
            while len(cand) > n + 1:
                if abs(err[cand[0]]) < abs(err[cand[-1]]): cand.pop(0)
                else: cand.pop()
            if len(cand) < n + 1: break
            idx = np.array(cand)
        return best
    order = np.argsort(tmap)
    for deg in (8, 9, 10):
        c, m = remez_samples(tmap[order], gs[order], deg)
        show('erfc: log(erfc x) + x^2 - log t = P%d(t), t=1/(1+x/2), abs (=rel of erfc)' % deg, c, m)

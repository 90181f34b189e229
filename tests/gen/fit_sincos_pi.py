#!/usr/bin/env python3
"""Fits the two polynomials of appear__sincos_pi (appear.h, special
functions) by the Remez exchange, in double, pure Python (no numpy):
    sin(pi t) = t P(t^2),      degree 9, minimax in relative error,
    cos(pi t) = 1 + t^2 Q(t^2), degree 10, minimax in absolute error,
on t in [-1/2, 1/2] (y = t^2 in [0, 1/4]). Run: python3 tests/gen/fit_sincos_pi.py
The coefficients are pasted into appear.h as float literals; the float error
of the result is measured by tests/test_special.c, not here."""
import math

def solve(A, b):
    n = len(b); M = [row[:] + [b[i]] for i, row in enumerate(A)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(M[r][c])); M[c], M[p] = M[p], M[c]
        for r in range(n):
            if r != c:
                f = M[r][c] / M[c][c]
                for k in range(c, n + 1): M[r][k] -= f * M[c][k]
    return [M[i][n] / M[i][i] for i in range(n)]

def remez(f, w, n, a, b, iters=30, grid=20000):
    """coefficients c_0..c_n of P minimising max |w(y) (f(y) - P(y))| on [a, b]"""
    xs = [a + (b - a) * (1 - math.cos(math.pi * i / (n + 1))) / 2 for i in range(n + 2)]
    G = [a + (b - a) * i / grid for i in range(grid + 1)]
    for _ in range(iters):
        A = [[x ** k for k in range(n + 1)] + [(-1) ** i / w(x)] for i, x in enumerate(xs)]
        sol = solve(A, [f(x) for x in xs]); c = sol[:n + 1]
        err = [w(x) * (f(x) - sum(ck * x ** k for k, ck in enumerate(c))) for x in G]
        ext, i = [], 0
        while i < len(G):                      # one extremum per run of equal sign
            sgn, j, best = err[i] >= 0, i, i
            while j < len(G) and (err[j] >= 0) == sgn:
                if abs(err[j]) > abs(err[best]): best = j
                j += 1
            ext.append(best); i = j
        if len(ext) >= n + 2:
            k = max(range(len(ext) - n - 1), key=lambda k: min(abs(err[e]) for e in ext[k:k + n + 2]))
            xs = [G[e] for e in ext[k:k + n + 2]]
    return c, max(abs(e) for e in err)

fs = lambda y: math.sin(math.pi * math.sqrt(y)) / math.sqrt(y) if y > 0 else math.pi
ws = lambda y: math.sqrt(y) / math.sin(math.pi * math.sqrt(y)) if y > 0 else 1 / math.pi
fq = lambda y: (math.cos(math.pi * math.sqrt(y)) - 1) / y if y > 0 else -math.pi ** 2 / 2
c, e = remez(fs, ws, 4, 0.0, 0.25)
print("sin(pi t) = t P(t^2), rel. error %.3g, P:" % e, ", ".join("%.9e" % x for x in c))
c, e = remez(fq, lambda y: max(y, 1e-12), 4, 0.0, 0.25)
print("cos(pi t) = 1 + t^2 Q(t^2), abs. error %.3g, Q:" % e, ", ".join("%.9e" % x for x in c))

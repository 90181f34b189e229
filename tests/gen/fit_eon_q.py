#!/usr/bin/env python3
"""Fits appear__eon_q (appear.h SECTION eon): Q(mu) = pi c1 - G(mu) of [Portsmouth25]'s
exact FON albedo, 1 - E_F(mu) = sigma A Q(mu) / pi. Q is analytic in theta (mu = cos theta),
zero at mu = 0 like mu, so Q / mu splits into its even and odd parts in theta:
    Q(mu) = mu (E(mu) + sin(theta) O(mu)),   E, O polynomials of degree 6,
one sqrt and two Horner chains instead of asin and two divisions. Weighted least squares
in relative error on 3000 Chebyshev nodes in theta, then Lawson reweighting toward minimax,
in double, pure Python. Run: python3 tests/gen/fit_eon_q.py
The reference Q is the cancellation-free double form (as tests/test_eon.c's); the float
error of the result is measured by tests/test_eon.c (suite eon), not here."""
import math

C1PI = math.pi / 2 - 2.0 / 3.0          # pi c1, c1 = 1/2 - 2/(3 pi)
DEG_E, DEG_O = 6, 6

def q(mu):
    si = math.sqrt((1 - mu) * (1 + mu)); t = 1 / (1 + si)
    return (C1PI * mu * t + si * si - (2.0 / 3.0) * si * (1 + si + si * si) * t) * mu + si * math.asin(mu)

def b(mu):                                # Q / mu, B(0) = 1
    return q(mu) / mu if mu > 0 else 1.0

def row(mu):
    si = math.sqrt((1 - mu) * (1 + mu))
    return [mu ** k for k in range(DEG_E + 1)] + [si * mu ** k for k in range(DEG_O + 1)]

def lstsq(A, y):
    """Householder QR least squares"""
    m, n = len(A), len(A[0]); A = [r[:] for r in A]; y = y[:]
    for k in range(n):
        x = [A[i][k] for i in range(k, m)]
        nx = math.copysign(math.sqrt(sum(v * v for v in x)), x[0])
        v = x[:]; v[0] += nx; nv = sum(t * t for t in v)
        for j in range(k, n):
            d = 2 * sum(v[i - k] * A[i][j] for i in range(k, m)) / nv
            for i in range(k, m): A[i][j] -= d * v[i - k]
        d = 2 * sum(v[i - k] * y[i] for i in range(k, m)) / nv
        for i in range(k, m): y[i] -= d * v[i - k]
    c = [0.0] * n
    for k in range(n - 1, -1, -1):
        c[k] = (y[k] - sum(A[k][j] * c[j] for j in range(k + 1, n))) / A[k][k]
    return c

N = 3000
nodes = [math.cos((i + 0.5) / N * math.pi / 2) for i in range(N)]
rows = [row(mu) for mu in nodes]
w = [1.0] * N
for it in range(12):                      # Lawson: weights grow where the error is large
    A = [[v * wi / b(mu) for v in r] for r, mu, wi in zip(rows, nodes, w)]
    c = lstsq(A, w[:])
    err = [abs(sum(x * y for x, y in zip(r, c)) / b(mu) - 1) for r, mu in zip(rows, nodes)]
    s = sum(wi * e for wi, e in zip(w, err))
    w = [wi * e / s * N for wi, e in zip(w, err)]
    w = [math.sqrt(wi) for wi in w]
worst = max(abs(sum(x * y for x, y in zip(row(mu), c)) / b(mu) - 1)
            for mu in [i / 50000 for i in range(50001)])
print("max rel. error of E(mu) + sin(theta) O(mu) against Q/mu on a 50001-point grid: %.3g" % worst)
print("E:", ", ".join("%.9ef" % v for v in c[:DEG_E + 1]))
print("O:", ", ".join("%.9ef" % v for v in c[DEG_E + 1:]))

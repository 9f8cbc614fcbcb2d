#!/usr/bin/env python3
"""Coefficients of trig::kernel_sin_wide (crates/rocking/src/trig.rs).

sin x = x + x z (S1 + z (S2 + ... + z^6 S8)), z = x^2, on |x| <= pi/2: a
Chebyshev fit of h(z) = (sin(sqrt z)/sqrt z - 1)/z of degree 7 on
[0, (pi/2)^2], computed with 50 significant digits, then rounded to doubles.
Prints the coefficients and the worst error on 2001 points of [0, pi/2] of
the polynomial with the rounded coefficients, evaluated exactly (it is below
4e-17; the double evaluation adds its own rounding, about one ulp).

Needs mpmath (pip install mpmath).
"""
import mpmath as mp

mp.mp.dps = 50
Z = (mp.pi / 2) ** 2


def h(z):
    if z == 0:
        return mp.mpf(-1) / 6
    r = mp.sqrt(z)
    return (mp.sin(r) / r - 1) / z


poly, err = mp.chebyfit(h, [0, Z], 8, error=True)
coefficients = [float(c) for c in reversed(poly)]
worst = 0
for i in range(2001):
    x = mp.pi / 2 * i / 2000
    z = x * x
    p = 0
    for c in reversed(coefficients):
        p = p * z + mp.mpf(c)
    worst = max(worst, abs(x + x * z * p - mp.sin(x)))
for k, c in enumerate(coefficients, 1):
    print(f"S{k} = {c!r}")
print(f"fit error {float(err):.2e}, worst error with rounded coefficients {float(worst):.2e}")

"""Reference pull-off forces of the Maugis–Dugdale sphere, 40 digits (mpmath).

Maugis, J. Colloid Interface Sci. 150, 243 (1992), in his reduced variables
Ā = a (K/(πΔγR²))^{1/3}, P̄ = P/(πΔγR), Δ̄ = δ (K²/(π²Δγ²R))^{1/3}, K = 4E*/3,
λ = 2σ0 (R/(πΔγK²))^{1/3}, m = c/a, s = √(m² − 1):

    (λĀ²/2)[s + (m² − 2) atan s] + (4λ²Ā/3)[s atan s − m + 1] = 1      (6.17)
    P̄ = Ā³ − λĀ²[s + m² atan s]
    Δ̄ = Ā² − (4/3) Ā λ s

and at Ā → 0 with C̄ = mĀ fixed: (πλ/4)C̄² + (4λ²/3)(π/2 − 1)C̄ = 1, P̄ = −(π/2)λC̄².
The pull-off −min P̄ over Ā ≥ 0 is found here by mpmath's root finder on m and
a golden-section search on Ā, independently of the Rust code
(`persson::adhesion::MaugisDugdale`). Prints `λ  pull-off  Ā at the minimum`.

    python3 tests/reference/maugis_dugdale_mpmath.py
"""
import mpmath as mp

mp.mp.dps = 40


def zone(a, lam):
    f = lambda s: (lam * a * a / 2 * (s + (s * s - 1) * mp.atan(s))
                   + 4 * lam * lam * a / 3 * (s * mp.atan(s) - s * s / (1 + mp.sqrt(1 + s * s))) - 1)
    lo, hi = mp.mpf(0), mp.mpf(1)
    while f(hi) < 0:
        hi *= 2
    return mp.findroot(f, (lo, hi), solver="anderson")


def force(a, lam):
    s = zone(a, lam)
    m2 = 1 + s * s
    return a ** 3 - lam * a * a * (s + m2 * mp.atan(s))


def detached(lam):
    aa, b = mp.pi * lam / 4, 4 * lam * lam / 3 * (mp.pi / 2 - 1)
    c = 2 / (b + mp.sqrt(b * b + 4 * aa))
    return -mp.pi / 2 * lam * c * c


def pull_off(lam):
    grid = [mp.mpf(k) / 100 for k in range(1, 401)]
    vals = [force(a, lam) for a in grid]
    k = min(range(len(vals)), key=lambda i: vals[i])
    best = detached(lam)
    if 0 < k < len(grid) - 1:
        lo, hi = grid[k - 1], grid[k + 1]
        g = (mp.sqrt(5) - 1) / 2
        for _ in range(120):
            x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
            if force(x1, lam) < force(x2, lam):
                hi = x2
            else:
                lo = x1
        a_min = (lo + hi) / 2
        p_min = force(a_min, lam)
        if p_min < best:
            return -p_min, a_min
    return -best, mp.mpf(0)


if __name__ == "__main__":
    for lam in ["0.1", "0.3", "1", "3"]:
        p, a = pull_off(mp.mpf(lam))
        print(lam, mp.nstr(p, 20), mp.nstr(a, 12))

"""Taylor coefficients of the flash-temperature heat kernel (src/friction/heat.rs).

    /work/venvs/friction/bin/python tests/reference/friction_heat_kernel.py

R(x) = B(x)/(3x²), B(x) = 2 erf(x) − 1 + e^{3x²} erfc(2x): h(q) = τ R(x) with
τ = π/(q v), x² = π D q / v. Prints R's Taylor coefficients (mpmath, 50 digits)
and reference values of R at a few x for the unit test.
"""
import mpmath as mp

mp.mp.dps = 50


def b(x):
    return 2 * mp.erf(x) - 1 + mp.exp(3 * x**2) * mp.erfc(2 * x)


c = mp.taylor(b, 0, 22)
print("const R_SERIES: [f64; 21] = [")
for k in range(2, 23):
    print(f"    {mp.nstr(c[k] / 3, 20, min_fixed=-1, max_fixed=-1)},")
print("];")
# R directly from the k-integral of the kernel, independent of the erf form:
# h/τ = (1/(π x²)) ∫_0^∞ dκ 4/(4+κ²) (1 − e^{−x²(1+κ²)})/(1+κ²)   (κ = k/q)
for x in ["1e-3", "0.05", "0.1", "0.3", "1", "3", "30"]:
    xx = mp.mpf(x)
    integral = mp.quad(lambda k: 4 / (4 + k**2) * (-mp.expm1(-xx**2 * (1 + k**2))) / (1 + k**2), [0, 1, mp.inf])
    r_int = integral / (mp.pi * xx**2)
    r_erf = b(xx) / (3 * xx**2)
    assert abs(r_int / r_erf - 1) < mp.mpf("1e-30"), (x, r_int, r_erf)
    print(f"    ({x}, {mp.nstr(r_erf, 20, min_fixed=-1, max_fixed=-1)}),")

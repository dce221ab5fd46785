"""Taylor coefficients of the flash-temperature heat kernel (src/friction/heat.rs).

    /work/venvs/friction/bin/python tests/reference/friction_heat_kernel.py

R(x) = B(x)/(3x²), B(x) = 2 erf(x) − 1 + e^{3x²} erfc(2x): h(q) = τ R(x) with
τ = π/(q v), x² = π D q / v. Prints R's Taylor coefficients (mpmath, 50 digits)
and reference values of R at a few x for the unit test.

Second, independent of the k-integral and of the erf form: R from the heat
equation itself, solved in the Laplace domain and inverted numerically
(`R_FROM_THE_HEAT_EQUATION` in tests/friction/flash.rs). In the units
z → q z, t → D q² t, u = D q² (ρc/Q̇0) T the model of heat.rs is
    u_t = u_zz − u + e^{−2z},  u_z(0, t) = 0 (insulated),  u(z, 0) = 0,
(the −u is the lateral mode cos(q x)); its transform at the surface is
    U(0, s) = 1/(s (s − 3)) − 2/(s (s − 3) √(s + 1)) = 1/(s √(s+1) (√(s+1) + 2)),
and R(x) = u(0, x²)/x². Talbot and de Hoog inversions agree to 40 digits.
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

# R from the heat equation (Laplace domain, numerical inversion).
U = lambda s: 1 / (s * mp.sqrt(s + 1) * (mp.sqrt(s + 1) + 2))
print("const R_FROM_THE_HEAT_EQUATION: [(f64, f64); 7] = [")
for x in ["0.02", "0.2", "0.7", "1", "2", "5", "20"]:
    xx = mp.mpf(x)
    talbot = mp.invertlaplace(U, xx**2, method="talbot") / xx**2
    dehoog = mp.invertlaplace(U, xx**2, method="dehoog") / xx**2
    assert abs(talbot / dehoog - 1) < mp.mpf("1e-30"), (x, talbot, dehoog)
    print(f"    ({x}, {mp.nstr(talbot, 20, min_fixed=-1, max_fixed=-1)}),")
print("];")

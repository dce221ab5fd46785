"""Independent check of the BGT reduction (src/asperity/bush.rs).

n, A/A0 and sigma0 of Bush-Gibson-Thomas with the geometric-mean sphere
(EllipticHertz::GeometricMean) by a direct integral over the summit height h and
principal curvatures k1 >= k2 > 0, from the Kac-Rice density of the Gaussian
vector (h, h_xx, h_yy, h_xy) written out from the moments (isotropy:
m40 = m04 = m4, m22 = m4/3), with |det H| = k1 k2 and the Jacobian k1 - k2 of
(h_xx, h_yy, h_xy) -> (k1, k2, theta) (checked numerically below): no
v-substitution, no kernel, no closed form in h as the crate and
asperity_reference.py use. SciPy tplquad, epsrel 1e-8.

Run: python3 tests/reference/asperity_bgt_kac_rice.py  (about 20 minutes)
Output (2026-11-25), m0 = m2 = 1, m4 = 5 (alpha = 5), E* = 1:
  1.0 n, A/A0, sigma0 = [0.07692703736367021, 0.05697923143739884, 0.04215714747715918]
  0.0 n, A/A0, sigma0 = [0.13288211241972414, 0.1823141183411628, 0.15718581710939533]
against tests/asperity.rs BGT (geometric mean, delta = 1 and 0): agreement
1e-15 (n, A/A0) and 1.8e-12, 3.8e-12 (sigma0; tplquad's tolerance).
"""
import numpy as np
from scipy import integrate
m0, m2, m4 = 1.0, 1.0, 5.0
alpha = m0*m4/m2**2
E = 1.0
# Gaussian vector (h, hxx, hyy, hxy) of an isotropic surface, profile moments:
# <h^2>=m0, <h hxx>=<h hyy>=-m2, <hxx^2>=<hyy^2>=m4, <hxx hyy>=m4/3, <hxy^2>=m4/3
# (isotropy: 2D moments of the 4th order m40 = m04 = m4, m22 = m4/3).
# Summits: gradient zero (gradient independent of h and Hessian, density of
# grad at 0: 1/(2 pi m2)), Hessian negative definite; Kac-Rice: |det H|.
C = np.array([[m0, -m2, -m2, 0], [-m2, m4, m4/3, 0], [-m2, m4/3, m4, 0], [0, 0, 0, m4/3]])
Ci = np.linalg.inv(C); det = np.linalg.det(C)
def dens(h, a, b, c):  # a=hxx, b=hyy, c=hxy
    x = np.array([h, a, b, c])
    return np.exp(-0.5*x@Ci@x)/np.sqrt((2*np.pi)**4*det)/(2*np.pi*m2)
# Principal curvatures k1 >= k2 > 0 of the summit: Hessian = -R(th) diag(k1,k2) R(th)^T.
# Change of variables (a, b, c) -> (k1, k2, th in [0, pi)): Jacobian (k1 - k2)/2... use
# dA db dc = (k1 - k2) dk1 dk2 dth / 2 * 2? compute: a = -(k1 c^2 + k2 s^2), b = -(k1 s^2 + k2 c^2), hxy = -(k1-k2) c s
def hess(k1, k2, th):
    cth, sth = np.cos(th), np.sin(th)
    return -(k1*cth**2 + k2*sth**2), -(k1*sth**2 + k2*cth**2), -(k1-k2)*cth*sth
# Jacobian |d(a,b,c)/d(k1,k2,th)| numerically once, to not rely on a hand factor.
def jac(k1, k2, th, e=1e-6):
    J = np.zeros((3, 3))
    for i, (d1, d2, d3) in enumerate([(e, 0, 0), (0, e, 0), (0, 0, e)]):
        p = np.array(hess(k1+d1, k2+d2, th+d3)); m = np.array(hess(k1-d1, k2-d2, th-d3))
        J[:, i] = (p-m)/(2*e)
    return abs(np.linalg.det(J))
print("jacobian check (k1-k2)?", jac(3.0, 1.0, 0.3), 2.0)
def integrand(kind, delta):
    def f(th, k2, k1, h):
        w = np.sqrt(m0)*0 + (h - delta)
        a, b, c = hess(k1, k2, th)
        base = dens(h, a, b, c)*k1*k2*(k1-k2)  # Kac-Rice |det H| = k1 k2, Jacobian k1 - k2
        R = 1/np.sqrt(k1*k2)
        if kind == 0: return base
        if kind == 1: return base*np.pi*R*w
        return base*4/3*E*np.sqrt(R)*w**1.5
    return f
s = np.sqrt(m4)
# Isotropy: the density does not depend on the orientation th, so its integral is a factor pi.
for delta in [1.0, 0.0]:
    out = []
    for kind in range(3):
        g = integrand(kind, delta)
        v, err = integrate.tplquad(lambda k2, k1, h: np.pi * g(0.0, k2, k1, h), delta, delta + 9,
                                   0, 12 * s, 0, lambda h, k1: k1, epsabs=0, epsrel=1e-8)
        out.append(v)
    print(delta, "n, A/A0, sigma0 =", out, flush=True)

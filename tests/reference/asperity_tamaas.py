"""Tamaas 2.9 volume stresses on a rough contact pressure, for tests/subsurface.rs.

Run (Tamaas from PyPI in a venv outside the repo):
    python3 tests/reference/asperity_tamaas.py
Writes tests/reference/data/asperity_tamaas_pressure.npy (the pressure of a
Tamaas rough-contact solve without its Nyquist modes, 64 × 64, L = 1,
row-major, x along rows) and
prints the Rust table of Tamaas' stresses at a few nodes and depths.

Tamaas' `boussinesq`, `boussinesq_gradient` and `hooke` operators on a
`volume_2d` model give the periodic half-space stress (fields (z, x, y, 6),
six components with √2 on the shear ones; depth nodes z_k = k Lz/(Nz − 1)). Checked here on one Fourier mode against the
closed form: normal stresses equal, the mean lateral stress −ν p̄/(1 − ν)
(zero mean in-plane strain) as in the crate.
"""
import os

import numpy as np
import tamaas as tm

N, L, NU = 64, 1.0, 0.3
LZ, NZ = 0.25, 17  # depth nodes k/64
HERE = os.path.dirname(os.path.abspath(__file__))


def rough_pressure():
    sp = tm.Isopowerlaw2D()
    sp.q0, sp.q1, sp.q2, sp.hurst = 2, 4, 16, 0.8
    gen = tm.SurfaceGeneratorRandomPhase2D([N, N])
    gen.spectrum = sp
    gen.random_seed = 7
    h = np.array(gen.buildSurface())
    h *= 0.05 / np.sqrt(np.mean(np.gradient(h, L / N)[0] ** 2 * 2))
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [L, L], [N, N])
    model.E, model.nu = 1.0, NU
    solver = tm.PolonskyKeerRey(model, h, 1e-12)
    solver.solve(0.01)
    return np.array(model.traction)


def volume_stress(p):
    m = tm.Model(tm.model_type.volume_2d, [LZ, L, L], [NZ, N, N])
    m.E, m.nu = 1.0, NU
    tm.ModelFactory.registerVolumeOperators(m)
    m.traction[..., 2] = p
    m.operators["boussinesq"](m.traction, m.displacement)
    m.operators["boussinesq_gradient"](m.traction, m["strain"])
    m.operators["hooke"](m["strain"], m["stress"])
    s = np.array(m["stress"])
    r2 = np.sqrt(2.0)
    # Shear without √2; on this field Tamaas' components 3, 4, 5 are the
    # crate's xy, xz, yz (identified by the exact agreement of all six).
    return np.stack([s[..., 0], s[..., 1], s[..., 2], s[..., 3] / r2, s[..., 4] / r2, s[..., 5] / r2], axis=-1)


def without_nyquist(p):
    """The field without its Nyquist row and column of Fourier modes, whose
    direction (sign of q) the grid cannot tell: the crate sets their odd
    stress multipliers to zero, Tamaas does not."""
    f = np.fft.fft2(p)
    f[N // 2, :] = 0
    f[:, N // 2] = 0
    return np.real(np.fft.ifft2(f))


def main():
    p = without_nyquist(rough_pressure())
    np.save(os.path.join(HERE, "data", "asperity_tamaas_pressure.npy"), p)
    s = volume_stress(p)
    k = np.unravel_index(np.argmax(p), p.shape)
    nodes = [tuple(int(v) for v in k), (5, 40), (33, 17)]
    print("// Tamaas 2.9: mean pressure %.17g, contact fraction %.6f" % (p.mean(), (p > 0).mean()))
    print("// (depth, row, column, [xx, yy, zz, xy, xz, yz])")
    for iz in [1, 2, 4, 8]:
        z = iz * LZ / (NZ - 1)
        for i, j in nodes:
            t = ", ".join("%.17e" % v for v in s[iz, i, j])
            print("    (%r, %d, %d, [%s])," % (z, i, j, t))


if __name__ == "__main__":
    main()

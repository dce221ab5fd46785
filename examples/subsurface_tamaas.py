"""The stress below a rough contact, ours against Tamaas 2.9's volume operators.

Solves one rough contact with `persson bem rough --subsurface` (periodic,
128², von Mises maps on two planes), then applies Tamaas's
`boussinesq_gradient` (surface traction -> strain on layers
z_k = k L_z/(N_z - 1)) and `hooke` to the same pressure field, and prints the
largest difference of the von Mises stress per plane over its peak.
Run (Tamaas in a venv outside the repo, `pip install tamaas`):

    python examples/subsurface_tamaas.py [PERSSON_BIN]
"""

import json
import pathlib
import subprocess
import sys
import tempfile

import numpy as np
import tamaas as tm

N, L, NU = 128, 1.0, 0.3
DEPTHS = [0.01, 0.02, 0.03, 0.05]  # on the Tamaas layers 0.01 * k (L_z = 0.05, N_z = 6)
BIN = sys.argv[1] if len(sys.argv) > 1 else "target/release/persson"


def ours(out):
    args = [BIN, "bem", "rough", "--hurst", "0.8", "--q-l", str(2 * np.pi), "--q-s",
            str(2 * np.pi * N / 4), "--rms-slope", "0.1", "--young", "1", "--poisson", str(NU),
            "--size", str(L), "--grid", str(N), "--pressure", "0.01",
            "--pressure-field", str(out / "p.npy"), "--subsurface", "--depth",
            ",".join(map(str, DEPTHS)), "--stress-field", str(out / "vm.npy"), "--json"]
    report = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
    p = np.load(out / "p.npy")
    maps = [np.load(out / f"vm_0_{j}.npy") for j in range(len(DEPTHS))]
    return report, p, maps


def tamaas_von_mises(p):
    lz, nz = 0.05, 6
    model = tm.ModelFactory.createModel(tm.model_type.volume_2d, [lz, L, L], [nz, N, N])
    model.E, model.nu = 1.0, NU
    tm.ModelFactory.registerVolumeOperators(model)
    model.traction[:] = 0
    model.traction[:, :, 2] = p
    strain = np.zeros((nz, N, N, 6))
    model.operators["boussinesq_gradient"](model.traction, strain)
    stress = np.zeros((nz, N, N, 6))
    model.operators["hooke"](strain, stress)
    vm = np.zeros((nz, N, N, 1))
    model.operators["von_mises"](stress, vm)
    return {round(k * lz / (nz - 1), 12): vm[k, :, :, 0] for k in range(nz)}


def main():
    with tempfile.TemporaryDirectory() as d:
        _, p, maps = ours(pathlib.Path(d))
    theirs = tamaas_von_mises(p)
    for z, mine in zip(DEPTHS, maps):
        t = theirs[round(z, 12)]
        print(f"z = {z} L: max |vm_ours - vm_tamaas| / max vm = "
              f"{np.abs(mine - t).max() / t.max():.3e} (peak ours {mine.max():.6e}, "
              f"Tamaas {t.max():.6e})")


if __name__ == "__main__":
    main()

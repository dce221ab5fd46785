"""Two scans of one rough surface for the multi-scale page (docs/multiscale.md).

A periodic self-affine surface (Hurst exponent 0.8, rolled off below
q_r = 2π/(0.5 mm), 256² points on 1 mm, rms height 1 µm) with Gaussian
Fourier amplitudes, cut into
- scan_coarse.npy: every 2nd point of the whole surface, 128² points, pixel
  7.8125 µm (1 mm), white noise 1 % of its rms height;
- scan_fine.npy: 128² points at full resolution from (40, 100), pixel
  3.90625 µm (0.5 mm), white noise 1 % of its rms height.
Both are float32 in metres, taken as non-periodic by `persson spectrum`.

Run: python3 docs/data/make_scans.py (numpy only; writes beside itself).
"""

import os

import numpy as np

N, L, H = 256, 1e-3, 0.8


def surface(rng):
    q = 2 * np.pi * np.fft.fftfreq(N, d=L / N)
    qx, qy = np.meshgrid(q, q)
    k = np.hypot(qx, qy)
    q_r = 2 * np.pi / 0.5e-3
    c = np.where(k > 0, np.maximum(k, q_r) ** (-2 * (1 + H)), 0.0)
    z = (rng.standard_normal((N, N)) + 1j * rng.standard_normal((N, N))) * np.sqrt(c)
    h = np.fft.ifft2(z).real
    return h * (1e-6 / h.std())


def noisy(h, rng):
    return h + 0.01 * h.std() * rng.standard_normal(h.shape)


def main():
    rng = np.random.default_rng(20261207)
    h = surface(rng)
    here = os.path.dirname(os.path.abspath(__file__))
    coarse = noisy(h[::2, ::2], rng)
    fine = noisy(h[40:168, 100:228], rng)
    np.save(os.path.join(here, "scan_coarse.npy"), coarse.astype(np.float32))
    np.save(os.path.join(here, "scan_fine.npy"), fine.astype(np.float32))


if __name__ == "__main__":
    main()

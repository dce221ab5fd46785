"""``persson.ensemble``: the FFT-BEM on seeds × grids of independent surfaces,
here or on Dask's distributed scheduler.

Each job is one (seed, N): the worker synthesises the surface from the
spectrum, the seed and N (the plan it receives holds the spectrum's recipe
and a few numbers, never a height map), solves it at every pressure and
sends back A/A0, ū and its solver figures. The report (mean and standard
error over the seeds per grid and pressure) is formed from those numbers by
the same Rust code whatever ran the jobs, so a run on a cluster equals the
serial run to the last digit (``persson compare ensemble`` on the CLI).
"""

from ._persson import _EnsemblePlan

# How long to wait for a scheduler given by its address.
CONNECT_TIMEOUT = "10s"


def _solve(plan, seed, grid):
    """One job on a worker (module-level, so Dask pickles it by reference)."""
    return plan.solve(seed, grid)


def _connect(client, timeout):
    """A dask.distributed Client from `client` (a Client, or a scheduler
    address), and whether it is ours to close."""
    if not isinstance(client, str):
        if not (hasattr(client, "submit") and hasattr(client, "gather")):
            raise ValueError(
                f"client = {client!r}: expected a dask.distributed Client or a scheduler address"
            )
        return client, False
    try:
        from dask.distributed import Client
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError(
            "client: running an ensemble on a scheduler needs dask.distributed "
            "(pip install 'dask[distributed]')"
        ) from e
    try:
        return Client(client, timeout=timeout, set_as_default=False), True
    except (OSError, TimeoutError) as e:
        raise ConnectionError(
            f"client = {client!r}: no Dask scheduler could be reached at this address "
            f"within {timeout} ({type(e).__name__}: {e})"
        ) from e


def ensemble(
    spectrum,
    contact_modulus,
    pressure,
    *,
    grid=64,
    levels=3,
    seeds=4,
    seed=1,
    pixels_per_wavelength=4.0,
    tolerance=1e-10,
    max_iterations=10000,
    client=None,
    threads=0,
    timeout=CONNECT_TIMEOUT,
):
    """The FFT-BEM on an ensemble of surfaces: seeds ``seed … seed + seeds − 1``
    on the grids ``grid/2^(levels−1) … grid`` (the surface of a seed is one
    band-limited realisation on every grid, as in ``compare``; q_s clipped to
    what the coarsest grid resolves with ``pixels_per_wavelength``), each
    solved at every nominal pressure (unit of E*) to ``tolerance``.

    Returns ``persson compare ensemble --json`` as a dict: per grid the mean
    and standard error over the seeds of A/A0 and ū at each pressure
    (``grids``), every job's numbers (``solves``) and ``warnings`` (also
    raised as ``UserWarning``).

    ``client``: None runs the jobs here on ``threads`` threads (0: one per
    core); a ``dask.distributed.Client`` or a scheduler address
    (``"tcp://host:8786"``) runs one Dask task per job (a worker needs
    ``persson`` installed). An address that cannot be reached within
    ``timeout`` raises ``ConnectionError`` naming it.
    """
    plan = _EnsemblePlan(
        spectrum, contact_modulus, pressure, grid, levels, seeds, seed,
        pixels_per_wavelength, tolerance, max_iterations,
    )
    jobs = plan.jobs()  # validates the input before any scheduler is contacted
    if client is None:
        return plan.run(threads)
    dask_client, ours = _connect(client, timeout)
    try:
        futures = [dask_client.submit(_solve, plan, s, n, pure=False) for s, n in jobs]
        solves = dask_client.gather(futures)
    finally:
        if ours:
            dask_client.close()
    return plan.gather(solves)

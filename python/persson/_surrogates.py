"""``persson.surrogates``: does a measured map make contact like random
surfaces of its spectrum? The FFT-BEM on the map and on K surrogates, here
or on Dask's distributed scheduler.

Each job is one surface: 0 the map, k the k-th surrogate. The worker makes
the surrogate from the map (which the plan carries, exactly) and its seed,
solves it at every pressure and sends back A/A0, the patches, the tail fit
and the pressure counts; the report (``persson surrogates --json``) is
formed from those numbers by the same Rust code whatever ran the jobs, so
a run on a cluster equals the serial run to the last digit.
"""

from ._ensemble import CONNECT_TIMEOUT, _connect
from ._persson import _SurrogatePlan


def _solve(plan, index):
    """One job on a worker (module-level, so Dask pickles it by reference)."""
    return plan.solve(index)


def surrogates(
    heights,
    size,
    contact_modulus,
    pressure,
    *,
    count=8,
    kind="phase",
    iterations=200,
    seed=1,
    boundary="periodic",
    tolerance=1e-8,
    spectrum=None,
    client=None,
    timeout=CONNECT_TIMEOUT,
):
    """The map ``heights`` (N × N float64 array, m; side ``size`` in m) against
    ``count`` surrogates of ``kind`` ``"phase"`` (the map's periodic spectrum
    with random phases: a Gaussian surface) or ``"amplitude-adjusted"`` (the
    map's own heights rearranged to its spectrum, IAAFT, at most
    ``iterations``), seeds ``seed … seed + count − 1``: the FFT-BEM on each at
    every nominal pressure (Pa, E* = ``contact_modulus``) with ``boundary``
    and ``tolerance``. With ``spectrum`` (a :class:`Spectrum`), Persson's A/A0
    on it up to the grid's πN/L beside them.

    Returns ``persson surrogates --json`` as a dict: per pressure the map's
    A/A0, the surrogates' mean, standard deviation and standard error, the
    ratio, ``z`` and whether it is ``significant`` (beyond Student's t at 95 %),
    the tails and patches; the height moments; ``warnings`` (also raised as
    ``UserWarning``).

    ``client``: None runs the jobs here; a ``dask.distributed.Client`` or a
    scheduler address runs one Dask task per surface (a worker needs
    ``persson`` installed).
    """
    plan = _SurrogatePlan(
        heights, size, contact_modulus, pressure, count, kind, iterations, seed,
        boundary, tolerance, spectrum,
    )
    jobs = plan.jobs()
    if client is None:
        return plan.gather([plan.solve(j) for j in jobs])
    dask_client, ours = _connect(client, timeout)
    try:
        futures = [dask_client.submit(_solve, plan, j, pure=False) for j in jobs]
        solves = dask_client.gather(futures)
    finally:
        if ours:
            dask_client.close()
    return plan.gather(solves)

"""Where a dataset's jobs run: worker processes on this machine, or Ray tasks on a cluster.

Both engines run the same function (:func:`mansion.dataset.job.run_job`) and yield its records
as the jobs finish, in whatever order; the dataset itself does not depend on that order. A job
never raises for a bad building; what reaches an engine is a worker that died (killed, out of
memory, a crash in native code): the buildings it was running are recorded as failed and the
others go on.
"""

from __future__ import annotations

import multiprocessing
import os
from collections.abc import Iterable, Iterator
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from pathlib import Path
from typing import Any

from mansion.dataset.job import JobSettings, record_failure, run_job, warm_up
from mansion.dataset.mix import BuildingSpec
from mansion.exceptions import InvalidInputError

__all__ = ["ENGINES", "run_local", "run_ray"]


def _lost(root: Path, spec: BuildingSpec, exc: BaseException) -> dict[str, Any]:
    """The failure record of a building whose worker died under it."""
    return record_failure(root, spec, exc, message=f"the worker died: {exc}")


def _stop(pool: ProcessPoolExecutor) -> None:
    """Ctrl-C or an early stop with jobs in flight: end the workers now rather than wait for
    their buildings (whose half-built folders the next run deletes)."""
    terminate = getattr(pool, "terminate_workers", None)  # Python 3.14
    if terminate is not None:
        terminate()
        return
    for process in list(getattr(pool, "_processes", {}).values()):
        process.terminate()


def run_local(
    specs: Iterable[BuildingSpec], settings: JobSettings, out: str | os.PathLike[str],
    *, workers: int = 1, address: str | None = None,
) -> Iterator[dict[str, Any]]:
    """Run the jobs in ``workers`` processes of this machine.

    At most ``workers`` jobs are in flight, so a worker that dies takes no queued building with
    it; the pool is then started afresh.
    """
    if address is not None:
        raise InvalidInputError("--address is for --engine ray; the local engine runs on this machine")
    if workers < 1:
        raise InvalidInputError(f"workers must be at least 1, got {workers}")
    root = Path(out)
    queue = list(specs)[::-1]
    # spawn, not fork: the parent may run threads (the progress bar's), which fork can deadlock
    context = multiprocessing.get_context("spawn")
    while queue:
        pool = ProcessPoolExecutor(max_workers=workers, mp_context=context, initializer=warm_up)
        running: dict[Future[dict[str, Any]], BuildingSpec] = {}
        broken = False
        try:
            while (queue or running) and not broken:
                while queue and len(running) < workers:
                    spec = queue.pop()
                    running[pool.submit(run_job, spec, settings, root)] = spec
                finished, _ = wait(running, return_when=FIRST_COMPLETED)
                for future in finished:
                    spec = running.pop(future)
                    try:
                        record = future.result()
                    except BrokenProcessPool as exc:
                        broken = True
                        record = _lost(root, spec, exc)
                    yield record
            if broken:
                # every job in flight died with the pool; the queue goes on in a new one
                for spec in running.values():
                    yield _lost(root, spec, BrokenProcessPool("a worker process died"))
                running.clear()
        finally:
            if running:
                _stop(pool)
            pool.shutdown(wait=True, cancel_futures=True)


def run_ray(
    specs: Iterable[BuildingSpec], settings: JobSettings, out: str | os.PathLike[str],
    *, workers: int = 1, address: str | None = None,
) -> Iterator[dict[str, Any]]:
    """Run the jobs as Ray tasks: on the cluster at ``address`` ("auto": the one this machine
    belongs to), or on a Ray started here with ``workers`` CPUs. Results stream back as they
    finish (``ray.wait``); twice the cluster's CPUs are kept in flight. ``out`` must be a path
    every node sees."""
    try:
        import ray
    except ModuleNotFoundError as exc:
        raise InvalidInputError("--engine ray needs Ray: pip install 'mansion[ray]'") from exc
    root = Path(out).resolve()
    started = not ray.is_initialized()
    if started:
        if address is not None:
            ray.init(address=address, log_to_driver=False)
        else:
            # the workers import the mansion this driver runs (a checkout on PYTHONPATH included)
            source = str(Path(__file__).resolve().parents[2])
            path = os.pathsep.join(p for p in (source, os.environ.get("PYTHONPATH", "")) if p)
            ray.init(
                num_cpus=workers, include_dashboard=False, log_to_driver=False,
                runtime_env={"env_vars": {"PYTHONPATH": path}},
            )
    try:
        task = ray.remote(num_cpus=1, max_retries=0)(run_job)
        window = 2 * max(1, int(ray.cluster_resources().get("CPU", workers)))
        queue = list(specs)[::-1]
        running: dict[Any, BuildingSpec] = {}
        try:
            while queue or running:
                while queue and len(running) < window:
                    spec = queue.pop()
                    running[task.remote(spec, settings, str(root))] = spec
                ready, _ = ray.wait(list(running), num_returns=1)
                for ref in ready:
                    spec = running.pop(ref)
                    try:
                        yield ray.get(ref)
                    except (ray.exceptions.RayError, OSError) as exc:
                        yield _lost(root, spec, exc)
        finally:
            for ref in running:
                ray.cancel(ref, force=True)
    finally:
        if started:
            ray.shutdown()


#: The engines by ``--engine`` name.
ENGINES = {"local": run_local, "ray": run_ray}

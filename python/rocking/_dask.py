"""Sweeps and inventories on a Dask cluster: the cases cut into contiguous blocks, one task per block.

Block ``i`` of ``B`` runs the cases ``floor(i·n/B) … floor((i+1)·n/B) − 1`` of
the ``n`` in case order (the blocks of ``rocking sweep --shard K/N``), in a
worker process with the GIL released; the columns of the blocks, gathered in
order and put end to end, are those of the local call. The tasks carry the
scenario (pickled as its TOML text) and the axes, or the sweep file's text: a
worker needs no file but the ground-motion records, read at the same paths.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any, Dict, List, Mapping, Optional, Tuple, Union

import numpy as np

from ._rocking import Scenario
from ._rocking import inventory_len_raw as _inventory_len_raw
from ._rocking import inventory_raw as _inventory_raw
from ._rocking import sweep_file_len_raw as _sweep_file_len_raw
from ._rocking import sweep_file_raw as _sweep_file_raw
from ._rocking import sweep_len_raw as _sweep_len_raw
from ._rocking import sweep_raw as _sweep_raw

if TYPE_CHECKING:
    import distributed

BLOCKS_PER_THREAD = 4
"""Blocks per worker thread by default: enough for the fast workers to take over the slow ones' share."""


def _blocks(client: "distributed.Client", cases: int, threads: Optional[int], blocks: Optional[int]) -> List[Tuple[int, int]]:
    """``(first, count)`` of each block, in case order."""
    if blocks is None:
        workers = sum(client.nthreads().values())
        blocks = BLOCKS_PER_THREAD * max(1, workers)
    if isinstance(blocks, bool) or not isinstance(blocks, int) or blocks < 1:
        raise ValueError(f"blocks must be None or an integer >= 1, got {blocks!r}")
    blocks = max(1, min(blocks, cases))
    starts = [i * cases // blocks for i in range(blocks + 1)]
    return [(starts[i], starts[i + 1] - starts[i]) for i in range(blocks)]


def _gather(client: "distributed.Client", futures: List[Any]) -> Dict[str, "np.ndarray"]:
    """The blocks' columns end to end, in case order."""
    parts: List[Dict[str, np.ndarray]] = client.gather(futures)
    out: Dict[str, np.ndarray] = {}
    for name in parts[0]:
        arrays = [p[name] for p in parts]
        dtypes = {a.dtype for a in arrays}
        # A block types its columns as the whole sweep does (rocking-python's
        # `column`), so they agree; if ever not, keep every value as an object.
        out[name] = np.concatenate(arrays) if len(dtypes) == 1 else np.concatenate([a.astype(object) for a in arrays])
    return out


def _task_threads(threads: Optional[int]) -> int:
    """Threads of one block: as asked, else 1 (the worker's threads run the blocks side by side)."""
    return 1 if threads is None else threads


def _run_block(scenario: Scenario, axes: Mapping[str, Any], threads: int, first: int, count: int) -> Dict[str, "np.ndarray"]:
    """The columns of cases ``first .. first + count`` (in a worker; the GIL is released while they run)."""
    return _sweep_raw(scenario, axes, threads, first, count)


def _run_file_block(path: str, text: str, threads: int, first: int, count: int) -> Dict[str, "np.ndarray"]:
    """The columns of cases ``first .. first + count`` of the sweep file ``path`` whose content is ``text``."""
    return _sweep_file_raw(path, threads, first, count, text)


def sweep_on(client: "distributed.Client", scenario: Scenario, axes: Mapping[str, Any], threads: Optional[int], blocks: Optional[int]) -> Dict[str, "np.ndarray"]:
    """``rocking.sweep(scenario, axes, client=client)``."""
    axes = dict(axes)
    cases = _sweep_len_raw(scenario, axes)  # checks the axes here, before any task
    # Each task carries the scenario (its TOML text, a few hundred bytes): no
    # scattered data whose release could race with the next sweep's tasks.
    futures = [
        client.submit(_run_block, scenario, axes, _task_threads(threads), first, count, pure=False)
        for first, count in _blocks(client, cases, threads, blocks)
    ]
    return _gather(client, futures)


def sweep_file_on(client: "distributed.Client", path: "os.PathLike[str] | str", threads: Optional[int], blocks: Optional[int]) -> Dict[str, "np.ndarray"]:
    """``rocking.sweep(path, client=client)``: the workers get the file's text."""
    given = os.fspath(path)
    with open(given, encoding="utf-8") as f:
        text = f.read()
    cases = _sweep_file_len_raw(given, text)  # checks the file here, before any task
    # Absolute: a worker in another directory finds the records relative to the file.
    absolute = os.path.abspath(given)
    futures = [
        client.submit(_run_file_block, absolute, text, _task_threads(threads), first, count, pure=False)
        for first, count in _blocks(client, cases, threads, blocks)
    ]
    return _gather(client, futures)


def _run_inventory_block(
    towers: str, towers_text: str, assess: Union[str, Mapping[str, Any]], assess_text: Optional[str], threads: int, first: int, count: int
) -> Dict[str, "np.ndarray"]:
    """The columns of towers ``first .. first + count`` of the towers' file ``towers`` whose content is ``towers_text``."""
    return _inventory_raw(towers, assess, threads, first, count, towers_text, assess_text)


def inventory_on(
    client: "distributed.Client", towers: "os.PathLike[str] | str", assess: Union[str, Mapping[str, Any]], threads: Optional[int], blocks: Optional[int]
) -> Dict[str, "np.ndarray"]:
    """``rocking.inventory(towers, assess, client=client)``: the workers get both files' text."""
    given = os.fspath(towers)
    with open(given, encoding="utf-8") as f:
        towers_text = f.read()
    assess_text: Optional[str] = None
    if isinstance(assess, str):
        with open(assess, encoding="utf-8") as f:
            assess_text = f.read()
        # Absolute: a worker in another directory finds the grid and the records relative to the file.
        assess = os.path.abspath(assess)
    count = _inventory_len_raw(given, assess, towers_text, assess_text)  # checks both files here, before any task
    futures = [
        client.submit(_run_inventory_block, given, towers_text, assess, assess_text, _task_threads(threads), first, n, pure=False)
        for first, n in _blocks(client, count, threads, blocks)
    ]
    return _gather(client, futures)

"""Rocking of a slender rigid tower on a building that may slide on its foundation.

Housner's rocking block on a Coulomb slider under horizontal ground
acceleration, integrated in Rust with every regime change (uplift, impact,
stick, slip, reversal, overturning) located exactly. The package reads the same
scenarios as the ``rocking`` command and gives the same numbers::

    import rocking

    scenario = rocking.Scenario.from_toml("examples/tower-on-church.toml")
    result = rocking.run(scenario)
    print(result.summary["max_theta_over_alpha"], result.summary["overturned"])
    theta = result.history["theta"]          # NumPy float64 array, one row per output_dt
    grid = rocking.sweep(scenario, {"ground.frequency": {"from": 3, "to": 7, "steps": 41}})

Errors raise one exception per kind, each with the one-line message of the
command line, ``file: key: what is wrong`` (``<dict>`` in place of the file
for a dict), and its parts as attributes ``.file``, ``.key`` and ``.reason``
(``None`` where it has none), so that a program need not parse the text:
``FileNotFoundError``/``OSError`` for a file that cannot be read (a scenario,
a sweep file, a record), :class:`InputError` (a ``ValueError``) for bad input,
:class:`SimulationError` (a ``RuntimeError``) for a numerical failure of a run.
"""

from __future__ import annotations

import json
import os
from typing import TYPE_CHECKING, Any, Dict, List, Mapping, Optional, Sequence, Union

from ._rocking import DERIVED_JSON as _DERIVED_JSON
from ._rocking import EVENT_COLUMNS as _EVENT_COLUMNS
from ._rocking import HISTORY_COLUMNS as _HISTORY_COLUMNS
from ._rocking import KEYS_JSON as _KEYS_JSON
from ._rocking import InputError, Scenario, SimulationError, __version__
from ._rocking import assess_raw as _assess_raw
from ._rocking import derived as _derived
from ._rocking import fragility_raw as _fragility_raw
from ._rocking import inventory_raw as _inventory_raw
from ._rocking import code_spectrum_raw as _code_spectrum_raw
from ._rocking import run_raw as _run_raw
from ._rocking import spectrum_raw as _spectrum_raw
from ._rocking import sweep_file_len_raw as _sweep_file_len_raw
from ._rocking import sweep_file_raw as _sweep_file_raw
from ._rocking import sweep_len_raw as _sweep_len_raw
from ._rocking import sweep_raw as _sweep_raw

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt
    import distributed
    import pandas

__all__ = ["DERIVED", "KEYS", "Assessment", "Fragility", "InputError", "Result", "Scenario", "ScenarioLike", "SimulationError", "assess", "code_spectrum", "derived", "fragility", "inventory", "run", "spectrum", "sweep", "__version__"]

ScenarioLike = Union[Scenario, Mapping[str, Any], str, "os.PathLike[str]"]
"""A :class:`Scenario`, a dict of its keys (:meth:`Scenario.from_dict`), or the path of a TOML file (:meth:`Scenario.from_toml`)."""

HISTORY_COLUMNS = _HISTORY_COLUMNS
"""The float64 columns of :attr:`Result.history` before ``regime`` and the extra points (``p1_dx``, ``p1_abs_acc``, …)."""

EVENT_COLUMNS = _EVENT_COLUMNS
"""The keys of each event in :attr:`Result.events`, the columns of ``events.csv``."""

KEYS: Sequence[Dict[str, Any]] = tuple(json.loads(_KEYS_JSON)["scenario"])
"""Every key of a scenario, described as ``rocking keys --json`` describes it:
``key`` (dotted), ``unit``, ``symbol``, ``label``, ``kind`` (``"number"``,
``"string"``, …), ``default``, ``range``, ``meaning``, ``example``,
``choices``, ``sweepable``; for a key of ``[ground]``, the ``types`` that take it."""

DERIVED: Sequence[Dict[str, str]] = tuple(json.loads(_DERIVED_JSON))
"""The quantities :func:`derived` returns, in order: ``name``, ``unit``, ``meaning``."""


def _as_scenario(scenario: ScenarioLike) -> Scenario:
    """The :class:`Scenario` of a scenario, a dict or a path."""
    if isinstance(scenario, Scenario):
        return scenario
    if isinstance(scenario, Mapping):
        return Scenario.from_dict(scenario)
    if isinstance(scenario, (str, os.PathLike)):
        return Scenario.from_toml(scenario)
    raise TypeError(f"expected a rocking.Scenario, a dict or a path, got {type(scenario).__name__}")


class Result:
    """The outcome of :func:`run`: what ``rocking run`` writes, as Python objects.

    Attributes:
        scenario: The scenario that was run.
        summary: The fields of ``summary.json`` (``max_theta_over_alpha``,
            ``overturned``, ``time_in_regime_s`` as a nested dict, ``wall_time_s``, …;
            ``min_effective_gravity_m_s2`` with a ``ground.vertical`` table;
            with ``[[block]]`` tables, ``max_seat_impulse_ratio``,
            ``overturned_block`` and each block's fields prefixed by its name:
            ``belfry_max_abs_theta_rad``, ``belfry_max_theta_over_alpha``,
            ``belfry_impacts``, ``belfry_first_uplift_time_s``, ``belfry_overturned``,
            ``belfry_max_friction_demand``);
            ``None`` where a quantity does not exist (the tower's without a tower).
        history: The columns of ``history.csv``: 1-D ``float64`` NumPy arrays
            ``t``, ``ground_acc``, ``theta``, ``theta_dot``, ``slip``, ``slip_vel``,
            ``top_dx``, ``top_abs_acc``, ``regime``, ``ground_acc_v`` (only with a
            ``ground.vertical`` table), then ``pK_dx``, ``pK_abs_acc``
            for each extra point K = 1, 2, … of ``tower.points``, then
            ``<name>_theta``, ``<name>_theta_dot`` for each block on the tower
            (its rotation relative to the block below; the order of
            ``history.csv``). ``regime`` is a NumPy array of dtype ``object`` holding
            the Python strings ``"rest"``, ``"rocking"``, ``"sliding"``,
            ``"rocking_sliding"``. One row every ``output_dt`` from ``t = 0`` to the
            end of the run (SI units: s, m/s², rad, rad/s, m, m/s).
        events: The rows of ``events.csv``, each a dict with the keys
            ``t``, ``kind`` (``"uplift"``, ``"impact"``, ``"rest"``, ``"slip"``,
            ``"stick"``, ``"reverse"``, ``"overturn"``; a block's prefixed by its
            name, ``"belfry_uplift"``, whose ``theta`` columns are then the block's), ``theta``,
            ``theta_dot_before``, ``theta_dot_after``, ``slip_vel``, ``slip``, ``regime``.
    """

    __slots__ = ("scenario", "summary", "history", "events")

    def __init__(self, scenario: Scenario, summary: Dict[str, Any], history: Dict[str, "np.ndarray"], events: List[Dict[str, Any]]) -> None:
        """Wraps the parts of a run (made by :func:`run`)."""
        self.scenario = scenario
        self.summary = summary
        self.history = history
        self.events = events

    def to_pandas(self) -> "pandas.DataFrame":
        """The history as a pandas DataFrame, one column per :attr:`history` array.

        Raises:
            ImportError: pandas is not installed.
        """
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("rocking.Result.to_pandas() needs pandas, which is not installed: pip install pandas") from e
        return pd.DataFrame(self.history)

    def __repr__(self) -> str:
        """A one-line description: the scenario, the rows, the events, whether it overturned."""
        rows = len(self.history["t"]) if "t" in self.history else 0
        return f"Result(scenario={self.scenario.name!r}, rows={rows}, events={len(self.events)}, overturned={self.summary.get('overturned')})"


def run(scenario: ScenarioLike) -> Result:
    """Runs one analysis, as ``rocking run`` does, with the GIL released.

    Args:
        scenario: A :class:`Scenario`, a dict of its keys or the path of a TOML file.

    Returns:
        A :class:`Result` with the summary, the history and the events.

    Raises:
        FileNotFoundError: The ground-motion record does not exist (``OSError`` if it cannot be read otherwise).
        ValueError: The scenario or its ground-motion record is invalid.
        RuntimeError: The integration failed (``file: integration failed at t = … s: …``).
        KeyboardInterrupt: Ctrl-C stops the run.
    """
    s = _as_scenario(scenario)
    summary, history, events = _run_raw(s)
    return Result(s, summary, history, events)


def derived(scenario: ScenarioLike) -> Dict[str, Optional[float]]:
    """The quantities derived from a scenario without running it (those ``rocking check`` prints).

    Keys: those of :data:`DERIVED`, in its order (``g_m_s2``, ``alpha_rad``,
    ``alpha_deg``, ``R_m``, ``p_rad_s``, ``restitution``, ``inertia_pivot_kg_m2``,
    ``tower_mass_kg``, ``sliding_mass_kg``, ``uplift_acceleration_g``,
    ``slip_acceleration_g``; named as in the summary where it has them);
    ``None`` for a quantity of an absent body.
    """
    return _derived(_as_scenario(scenario))


AxisValues = Union[Sequence[Any], Mapping[str, Any], "npt.ArrayLike"]
"""The values of one sweep axis: a list, or ``{"from": a, "to": b, "steps": n}`` (or ``"step": h``)."""


def sweep(
    scenario: ScenarioLike,
    axes: Optional[Mapping[str, AxisValues]] = None,
    *,
    threads: Optional[int] = None,
    client: Optional["distributed.Client"] = None,
    blocks: Optional[int] = None,
) -> Dict[str, "np.ndarray"]:
    """Runs a parametric study, as ``rocking sweep`` does, on all cores with the GIL released.

    Args:
        scenario: The base case: a :class:`Scenario`, a dict of its keys or the path of a
            TOML file; with ``axes=None``, the path of a sweep file (a scenario with a
            ``[sweep]`` table).
        axes: The ``[sweep]`` table of a sweep file: dotted scenario keys mapped to a list
            of values or ``{"from": 3.0, "to": 7.0, "steps": 41}`` (or ``"step": 0.1``), e.g.
            ``{"ground.frequency": {"from": 3, "to": 7, "steps": 41}, "ground.amplitude": [0.3, 0.5]}``.
            A block's keys are named by the block: ``{"belfry.width": [1.5, 2.0, 2.4]}``.
            Every combination is one case; the first axis varies slowest.
        threads: Worker threads; ``None`` for one per core (or ``RAYON_NUM_THREADS``).
            With a ``client``: the threads of each block (default 1: the Dask
            worker's threads run blocks side by side, each a core).
        client: A ``dask.distributed.Client``: the cases are cut into contiguous
            blocks, each run by a task in a worker process with the GIL released,
            and their columns put end to end: the same columns as the local call.
            Dask is an optional extra: ``pip install "rocking[dask]"``. The workers
            read the ground-motion records at the same paths as this process.
        blocks: With a ``client``, the number of blocks (default: 4 per worker
            thread of the cluster, at most one per case).

    Returns:
        The columns of ``sweep.csv``, one row per case in case order: the swept values
        first (named by their keys), then every scalar field of the summary but
        ``wall_time_s`` (nested ones dotted: ``time_in_regime_s.rest``), then ``error``.
        Numbers are ``float64`` arrays (``NaN`` where the CSV field is empty: a quantity
        that does not exist, or any result of a failed case); booleans are ``bool``
        arrays, or ``object`` arrays of ``True`` / ``False`` / ``None`` when a field
        is empty (``will_overturn`` while ground motion remains after the end, any
        flag of a failed case: a null stays ``None``, never ``False``); text is an
        ``object`` array of ``str`` (``""`` where empty). A case that fails (a bad combination, a numerical
        failure) does not stop the others: its message is in ``error``.

    Raises:
        FileNotFoundError: The sweep file or a record does not exist (``OSError`` if it cannot be read otherwise).
        ValueError: The base scenario or an axis is invalid (``file: sweep."key": …``), or
            ``threads`` is outside 1..=4096 (the command's limit).
        KeyboardInterrupt: Ctrl-C stops the sweep (the cases under way stop at their next event).
    """
    if axes is None:
        if not isinstance(scenario, (str, os.PathLike)):
            raise TypeError("rocking.sweep(): give the axes, or the path of a sweep file (with a [sweep] table)")
        if client is None:
            return _sweep_file_raw(scenario, threads)
        from ._dask import sweep_file_on

        return sweep_file_on(client, scenario, threads, blocks)
    s = _as_scenario(scenario)
    if client is None:
        return _sweep_raw(s, axes, threads)
    from ._dask import sweep_on

    return sweep_on(client, s, axes, threads, blocks)


class Fragility:
    """The outcome of :func:`fragility`: what ``rocking fragility`` writes, as NumPy columns.

    Attributes:
        stripes: The columns of ``stripes.csv``, one row per (record, level) in
            case order: ``record`` (object array of ``str``, the path as the glob
            gave it), ``level``, ``scale`` (float64), then the scalar fields of
            ``summary.json`` as :func:`sweep` gives them, then ``error``
            (``""`` for a case that ran).
        fragility: The columns of ``fragility.csv``, one entry per limit state:
            ``limit_state``, ``median`` and ``beta`` (float64, ``NaN`` where no fit
            exists), ``cases``, ``exceeded`` (int64), ``method`` (why there is no
            fit, when there is none).
        fractions: The columns of ``fractions.csv``: ``limit_state``, ``level``,
            ``cases``, ``exceeded``, one entry per limit state and level.
        hazard: With a ``[site]``, the columns of ``hazard.csv`` (the site's
            hazard curve of surface PGA at the grid's nine return periods); else ``None``.
        risk: With a ``[site]``, the columns of ``risk.csv`` (each limit state's
            mean annual frequency of exceedance, ``NaN`` where no fit exists); else ``None``.
    """

    def __init__(
        self,
        stripes: Dict[str, "np.ndarray"],
        fragility: Dict[str, "np.ndarray"],
        fractions: Dict[str, "np.ndarray"],
        hazard: Optional[Dict[str, "np.ndarray"]] = None,
        risk: Optional[Dict[str, "np.ndarray"]] = None,
    ) -> None:
        self.stripes = stripes
        self.fragility = fragility
        self.fractions = fractions
        self.hazard = hazard
        self.risk = risk

    def __repr__(self) -> str:
        n = len(next(iter(self.stripes.values()))) if self.stripes else 0
        return f"<rocking.Fragility: {n} cases, limit states {list(self.fragility['limit_state'])}>"


def fragility(study: Union[str, "os.PathLike[str]", Mapping[str, Any]], *, threads: Optional[int] = None) -> Fragility:
    """Runs a fragility study, as ``rocking fragility`` does, on all cores with the GIL released.

    Args:
        study: The path of a study file (a scenario without ``[ground]`` plus a
            ``[study]`` table), or a dict with the same keys (``study.limit_state``
            a list of dicts; record patterns then relative to the current directory).
        threads: Worker threads (default: one per core).

    Returns:
        A :class:`Fragility`: the stripes, the fitted lognormal fragility of each
        limit state (binomial maximum likelihood, Baker 2015) and the observed fractions.

    Raises:
        ValueError: The study is invalid (``file: study.key: …``).
        OSError: The study file cannot be read.
        KeyboardInterrupt: Ctrl-C stops the study (the cases under way stop at their next event).
    """
    raw = _fragility_raw(study, threads)
    return Fragility(raw["stripes"], raw["fragility"], raw["fractions"], raw.get("hazard"), raw.get("risk"))


PathLike = Union[str, "os.PathLike[str]"]


def _csv_columns(text: Optional[str]) -> Optional[Dict[str, "np.ndarray"]]:
    """The columns of a CSV table: numbers as float64 arrays, others as object arrays (empty cells None)."""
    if text is None:
        return None
    import csv
    import io

    import numpy as np

    rows = list(csv.reader(io.StringIO(text)))
    out: Dict[str, "np.ndarray"] = {}
    for i, name in enumerate(rows[0]):
        cells = [row[i] for row in rows[1:]]
        try:
            out[name] = np.array([float(c) for c in cells], dtype=np.float64)
        except ValueError:
            out[name] = np.array([c if c != "" else None for c in cells], dtype=object)
    return out


class Assessment:
    """The outcome of :func:`assess`: what ``rocking assess`` writes.

    Attributes:
        json: ``assessment.json`` as a dict: ``capacity``, ``sites``, ``checks``
            (each with ``limit_state``, ``method``, ``demand``, ``capacity``,
            ``unit``, ``holds``, ``ag_capacity_g``, ``zeta_E``), ``governing``, ``dynamic``.
        checks: ``json["checks"]`` (the tower's).
        governing: ``json["governing"]``, the check of least ζ_E (with blocks
            on the tower, over every mechanism, its ``mechanism`` named).
        mechanisms: ``json["mechanisms"]`` with blocks on the tower (each
            mechanism's ``name``, ``block``, ``capacity``, ``checks``,
            ``governing``, ``dynamic``, the tower's first), else empty.
        capacity: The columns of ``capacity.csv`` (``d_star_m``, ``a_star_m_s2``).
        records: The columns of ``records.csv`` (with a record set, else None).
        spectra: The columns of ``spectra.csv`` (with a record set, else None).
    """

    def __init__(self, raw: Mapping[str, Optional[str]]) -> None:
        import json

        self.json: Dict[str, Any] = json.loads(raw["assessment"] or "{}")
        self.checks: List[Dict[str, Any]] = self.json["checks"]
        self.governing: Optional[Dict[str, Any]] = self.json["governing"]
        self.mechanisms: List[Dict[str, Any]] = self.json.get("mechanisms", [])
        self.capacity = _csv_columns(raw["capacity"])
        self.records = _csv_columns(raw["records"])
        self.spectra = _csv_columns(raw["spectra"])

    def __repr__(self) -> str:
        g = self.governing
        return f"<rocking.Assessment: {len(self.checks)} checks, governing {g['limit_state']} {g['method']} zeta_E={g['zeta_E']:.3g}>" if g else "<rocking.Assessment>"


def assess(file: Union[str, "os.PathLike[str]", Mapping[str, Any]], *, threads: Optional[int] = None) -> Assessment:
    """Assesses a tower to the code, as ``rocking assess`` does (Circolare 2019
    §C8.7.1.2.1 with the NTC 2018 or EN 1998-1 spectra): the capacity, the
    activation, linear and non-linear kinematic checks and, with a record set,
    the non-linear dynamic checks (on all cores with the GIL released). With
    ``[[block]]`` tables each block, with those above it, is a mechanism of
    its own (``Assessment.mechanisms``), and the governing check is taken
    over every mechanism.

    Args:
        file: The path of an assessment file, or a dict with its keys (relative
            paths of a dict resolve against the current directory).
        threads: Worker threads of the dynamic checks (default: one per core).

    Returns:
        An :class:`Assessment`.

    Raises:
        FileNotFoundError: The file (or its grid, or a record) does not exist.
        ValueError: A key is wrong (``file: key: what is wrong``).
    """
    raw = file if isinstance(file, Mapping) else os.fspath(file)
    return Assessment(_assess_raw(raw, threads))


def inventory(
    towers: PathLike,
    assess: Union[PathLike, Mapping[str, Any]],
    *,
    threads: Optional[int] = None,
    client: Optional["distributed.Client"] = None,
    blocks: Optional[int] = None,
) -> Dict[str, "np.ndarray"]:
    """Assesses every bell tower of a town, as ``rocking inventory`` does, on all cores with the GIL released.

    Each row of ``towers`` is the assessment file with the row's cells set in
    it (a dotted column is a key, ``soil``, ``topography``, ``ag_SLV``… are the
    site's, ``lon``, ``lat`` the place on its hazard grid; an empty cell keeps
    the file's value), assessed as :func:`assess` would assess it: the
    kinematic checks, and the dynamic ones when the file has a record set.

    Args:
        towers: The path of the towers' CSV file (``id``, ``name``, ``lon``, ``lat``, …).
        assess: The assessment file every tower starts from: its path, or a dict
            with its keys (relative paths of a dict resolve against the current directory).
        threads: Worker threads; ``None`` for one per core. With a ``client``: the
            threads of each block (default 1).
        client: A ``dask.distributed.Client``: the towers are cut into contiguous
            blocks, each assessed by a task in a worker process, and their columns
            put end to end: the same columns as the local call. The workers read the
            hazard grid and the records at the same paths as this process.
        blocks: With a ``client``, the number of blocks (default: 4 per worker
            thread of the cluster, at most one per tower).

    Returns:
        The columns of ``inventory.csv``, one row per tower in input order: ``id``,
        ``name`` (object arrays of ``str``), ``lon``, ``lat`` (float64, ``NaN`` where
        not a number), the tower's inputs (``tower.width``, ``tower.height``, ``soil``,
        ``topography``, then the towers' file's other columns: the values it was
        assessed with), the site's ``ag_<LS>_g`` of each limit state, each check's
        ``<LS>_<method>_ag_capacity_g`` and ``<LS>_<method>_zeta_E`` (float64, ``NaN``
        where not completed), ``zeta_E`` (the governing, least one),
        ``zeta_E_is_lower_bound`` (bool: the governing ζ_E is only the top of the
        search or of the λ scan), ``governing`` (``"SLV linear_kinematic"``) and
        ``error`` (``""``, or the one line of a bad row: the other towers are assessed).

    Raises:
        FileNotFoundError: A file does not exist (``OSError`` if it cannot be read otherwise).
        ValueError: The assessment file is invalid by itself, a record of its set is
            malformed, or the towers' file has a bad header.
        KeyboardInterrupt: Ctrl-C stops the inventory after the towers under way.
    """
    raw_assess: Union[str, Mapping[str, Any]] = assess if isinstance(assess, Mapping) else os.fspath(assess)
    if client is None:
        return _inventory_raw(os.fspath(towers), raw_assess, threads)
    from ._dask import inventory_on

    return inventory_on(client, towers, raw_assess, threads, blocks)


def spectrum(
    records: Union[PathLike, Sequence[PathLike]],
    *,
    damping: float = 5.0,
    periods: "tuple[float, float, int]" = (0.02, 4.0, 100),
) -> Dict[str, "np.ndarray"]:
    """Response spectra of record files, as ``rocking spectrum RECORD...`` writes them.

    The pseudo-acceleration ``PSA(T, ξ) = ω² max|x|`` of the linear oscillator,
    exact for the piecewise-linear record (Nigam & Jennings 1969), the maximum
    over the sample instants of the record and of a free tail of two periods.

    Args:
        records: A record file or a list of them (AT2, ESM ASCII, or CSV with a
            time column in g; the format is guessed, as for ``[ground]``).
        damping: Damping ratio, % of critical, in [0, 100).
        periods: ``(from, to, count)``: ``count`` log-spaced periods (s).

    Returns:
        ``{"period_s": array, <file name>: array, ...}``: the periods and each
        record's spectrum in g (float64 NumPy arrays), the columns of ``spectra.csv``.

    Raises:
        FileNotFoundError: A record file does not exist (``OSError`` for other read failures).
        ValueError: A record is malformed, or the damping or the periods are out of range.
    """
    paths = [records] if isinstance(records, (str, os.PathLike)) else list(records)
    return dict(_spectrum_raw([os.fspath(p) for p in paths], float(damping), (float(periods[0]), float(periods[1]), int(periods[2]))))


def code_spectrum(
    site: Union[PathLike, Mapping[str, Any]],
    *,
    periods: "tuple[float, float, int]" = (0.02, 4.0, 100),
) -> Dict[str, "np.ndarray"]:
    """The code spectra of an assessment file's site, as ``rocking spectrum --site`` writes them.

    Args:
        site: The path of an assessment file, or a dict with its keys (at least
            ``{"site": {...}}``: ``code``, ``soil``, ``topography``, and a table per
            limit state, ``{"SLV": {"ag": 0.155, "F0": 2.47, "Tc_star": 0.36}}``, or
            ``grid``, ``lon``, ``lat``, ``VN``, ``CU``; paths of a dict are relative
            to the current directory).
        periods: ``(from, to, count)``: ``count`` log-spaced periods (s).

    Returns:
        ``{"period_s": array, "Se_SLV_g": array, "SDe_SLV_m": array, "Se_SLV_8pct_g": array, ...}``:
        for each limit state its elastic spectrum (g) and displacement spectrum (m)
        at 5%, and at the damping of its non-linear kinematic check (8% at SLV, 10% at SLC).

    Raises:
        FileNotFoundError: The file (or its hazard grid) does not exist.
        ValueError: A key is wrong (``file: site.key: what is wrong``).
    """
    raw = site if isinstance(site, Mapping) else os.fspath(site)
    return dict(_code_spectrum_raw(raw, (float(periods[0]), float(periods[1]), int(periods[2]))))

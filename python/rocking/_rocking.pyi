"""Type stubs of the extension module ``rocking._rocking`` (Rust, PyO3). Use the ``rocking`` package."""

import os
from typing import Any, Dict, List, Mapping, Optional, Tuple, Union

import numpy as np

__version__: str
HISTORY_COLUMNS: Tuple[str, ...]
"""The float64 columns of the history before ``regime`` and the extra points (from the library's column list)."""
EVENT_COLUMNS: Tuple[str, ...]
"""The keys of each event, the columns of ``events.csv`` (from the library's column list)."""
KEYS_JSON: str
"""Every key's description, as ``rocking keys --json`` prints it."""
DERIVED_JSON: str
"""The derived quantities' descriptions: ``[{"name", "unit", "meaning"}, …]``."""

# Errors, one exception per kind, each with the one-line message of the command
# and its parts as attributes (.file, .key, .reason; None where it has none):
#   FileNotFoundError / OSError  a file cannot be read (the scenario, a sweep file, a record)
#   InputError (a ValueError)    bad input (``file: key: what is wrong``)
#   SimulationError (a RuntimeError)  a numerical failure of a run
#   KeyboardInterrupt            Ctrl-C (or the exception of the SIGINT handler) during a long call

class InputError(ValueError):
    """Bad input: ``str()`` is ``file: key: reason``, the command's line."""

    file: Optional[str]
    key: Optional[str]
    reason: str

class SimulationError(RuntimeError):
    """A run that failed numerically: ``str()`` is the command's line."""

    file: Optional[str]
    key: Optional[str]
    reason: str

class Scenario:
    """A validated scenario: a tower, a building or both, a ground motion, initial state and settings."""

    @staticmethod
    def from_toml(path: Union[str, "os.PathLike[str]"]) -> "Scenario":
        """Reads and validates a scenario file (TOML); a relative record path is resolved against its folder.

        Raises ``ValueError`` (``file: key: what is wrong``), or ``FileNotFoundError`` (``OSError``)
        if the file cannot be read, with the command's message (``cannot read file: …``).
        """
        ...
    @staticmethod
    def from_dict(d: Mapping[str, Any]) -> "Scenario":
        """Validates a scenario given as a dict with the keys of the TOML file (sections as nested dicts).

        ``None`` is an absent key; the vertical motion is the nested dict ``ground["vertical"]``
        (the keys of ``ground``). A relative ``ground.file`` or ``ground.vertical.file`` is resolved
        against the current directory.
        Raises ``ValueError`` (``<dict>: key: what is wrong``), also for a list or dict that
        contains itself or is nested more than 16 deep.
        """
        ...
    def to_dict(self) -> Dict[str, Any]:
        """The keys as given (no defaults filled in), ``ground.file`` and ``ground.vertical.file`` as the absolute paths of the records read."""
        ...
    @property
    def name(self) -> str:
        """The scenario's ``name`` (default: the file stem, or ``<dict>``)."""
        ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, str]]:
        """Pickles as the TOML text of the scenario and its origin (made absolute)."""
        ...
    @property
    def origin(self) -> str:
        """The file the scenario was read from, or ``<dict>``."""
        ...

def run_raw(scenario: Scenario) -> Tuple[Dict[str, Any], Dict[str, "np.ndarray"], List[Dict[str, Any]]]:
    """Runs a scenario with the GIL released: ``(summary, history, events)``; see ``rocking.run``.

    Raises ``FileNotFoundError``/``OSError`` (the record cannot be read), ``ValueError`` (bad input),
    ``RuntimeError`` (a numerical failure); Ctrl-C stops the run.
    """
    ...

def derived(scenario: Scenario) -> Dict[str, Optional[float]]:
    """The quantities derived from a scenario without running it; see ``rocking.derived``."""
    ...

def sweep_raw(
    scenario: Scenario, axes: Mapping[str, Any], threads: Optional[int] = None, first: int = 0, count: Optional[int] = None
) -> Dict[str, "np.ndarray"]:
    """Runs cases ``first .. first + count`` (default: all) of a sweep of ``scenario`` over ``axes`` with the GIL released; see ``rocking.sweep``.

    Raises ``ValueError`` (bad input, ``threads`` outside 1..=4096), ``FileNotFoundError``/``OSError``.
    """
    ...

def sweep_len_raw(scenario: Scenario, axes: Mapping[str, Any]) -> int:
    """The number of cases of a sweep of ``scenario`` over ``axes`` (checked as ``sweep_raw`` checks them)."""
    ...

def sweep_file_raw(
    path: Union[str, "os.PathLike[str]"], threads: Optional[int] = None, first: int = 0, count: Optional[int] = None, text: Optional[str] = None
) -> Dict[str, "np.ndarray"]:
    """Runs cases ``first .. first + count`` (default: all) of a sweep file (``text``: its content, if given); see ``rocking.sweep``.

    Raises ``FileNotFoundError``/``OSError`` (the file cannot be read), ``ValueError`` (bad input).
    """
    ...

def sweep_file_len_raw(path: Union[str, "os.PathLike[str]"], text: Optional[str] = None) -> int:
    """The number of cases of a sweep file (``text``: its content, if given)."""
    ...

def fragility_raw(
    study: Union[str, "os.PathLike[str]", Mapping[str, Any]], threads: Optional[int] = None
) -> Dict[str, Dict[str, "np.ndarray"]]:
    """Runs a fragility study with the GIL released: ``{"stripes", "fragility", "fractions"}`` columns (and ``"hazard"``, ``"risk"`` with a ``[site]``); see ``rocking.fragility``.

    Raises ``FileNotFoundError``/``OSError`` (a file cannot be read), ``ValueError`` (bad input).
    """
    ...

def assess_raw(file: Union[str, "os.PathLike[str]", Mapping[str, Any]], threads: Optional[int] = None) -> Dict[str, Optional[str]]:
    """Assesses a tower to the code with the GIL released: ``{"assessment": JSON text, "capacity", "records", "spectra": CSV text or None}``; see ``rocking.assess``.

    Raises ``FileNotFoundError``/``OSError`` (a file cannot be read), ``ValueError`` (bad input).
    """
    ...

def inventory_raw(
    towers: Union[str, "os.PathLike[str]"],
    assess: Union[str, "os.PathLike[str]", Mapping[str, Any]],
    threads: Optional[int] = None,
    first: int = 0,
    count: Optional[int] = None,
    towers_text: Optional[str] = None,
    assess_text: Optional[str] = None,
) -> Dict[str, "np.ndarray"]:
    """Assesses towers ``first .. first + count`` (default: all) of a town with the GIL released; see ``rocking.inventory``.

    Raises ``FileNotFoundError``/``OSError`` (a file cannot be read), ``ValueError`` (bad input).
    """
    ...

def inventory_len_raw(
    towers: Union[str, "os.PathLike[str]"],
    assess: Union[str, "os.PathLike[str]", Mapping[str, Any]],
    towers_text: Optional[str] = None,
    assess_text: Optional[str] = None,
) -> int:
    """The number of towers of a town (both files checked as ``inventory_raw`` checks them)."""
    ...

def spectrum_raw(records: List[str], damping: float, periods: Tuple[float, float, int]) -> Dict[str, "np.ndarray"]:
    """Response spectra (g) of record files: ``{"period_s", <file name>...}``; see ``rocking.spectrum``.

    Raises ``FileNotFoundError``/``OSError`` (a file cannot be read), ``ValueError`` (bad input).
    """
    ...

def code_spectrum_raw(site: Union[str, Mapping[str, Any]], periods: Tuple[float, float, int]) -> Dict[str, "np.ndarray"]:
    """Code spectra of an assessment file's site: ``{"period_s", "Se_SLV_g", ...}``; see ``rocking.code_spectrum``.

    Raises ``FileNotFoundError``/``OSError`` (a file cannot be read), ``ValueError`` (bad input).
    """
    ...

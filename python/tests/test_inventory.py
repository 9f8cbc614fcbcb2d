"""`rocking.inventory`: the columns of the `rocking inventory` command's
inventory.csv, bit for bit (each number the float that the command's shortest
round-trip text reads back to), for the example town, for bad rows (the same
error line each), for a record set (the dynamic checks), and from a dict."""

from __future__ import annotations

import csv
import math
from pathlib import Path
from typing import Dict, List

import numpy as np
import pytest
import rocking

from conftest import EXAMPLES, ROOT, run_cli

TOWN = EXAMPLES / "town"
GRID = ROOT / "data" / "hazard" / "synthetic_grid.txt"
RECORDS = ROOT / "data" / "records" / "synthetic"


def command_inventory(cli: Path, towers: Path, assess: Path, out: Path, status: int = 0) -> List[Dict[str, str]]:
    """The rows of the command's inventory.csv."""
    done = run_cli(cli, "inventory", towers, "--assess", assess, "--out", out)
    assert done.returncode == status, done.stderr
    with open(out / "inventory.csv", newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def assert_table_is_csv(table: Dict[str, np.ndarray], rows: List[Dict[str, str]]) -> None:
    """Every column of `table` is that of the CSV rows: the same names in the
    same order, text equal, numbers equal to the CSV's text read as a float
    (exactly: the command writes each float's shortest round-trip form), NaN
    where the CSV is empty, a boolean its true or false; a column of mixed
    cells (an input column with a bad row's text) holds each as its own kind."""
    assert list(table) == list(rows[0])
    for name, column in table.items():
        assert len(column) == len(rows), name
        for i, row in enumerate(rows):
            text, got = row[name], column[i]
            if column.dtype == np.float64:
                if text == "":
                    assert math.isnan(got), (name, i, got)
                else:
                    assert got == float(text), (name, i, got, text)
            elif column.dtype == np.bool_:
                # zeta_E_is_lower_bound: the CSV's true/false.
                assert text in ("true", "false") and bool(got) == (text == "true"), (name, i, got, text)
            elif got is None:
                # An object column's empty cell (a failed row's lower bound).
                assert text == "", (name, i, got, text)
            elif isinstance(got, bool):
                assert text == ("true" if got else "false"), (name, i, got, text)
            elif isinstance(got, (int, float)):
                # An input column holding numbers and a bad row's text ("tall").
                assert got == float(text), (name, i, got, text)
            else:
                assert got == text, (name, i, got, text)


def test_the_example_town_equals_the_command(cli: Path, tmp_path: Path) -> None:
    towers, assess = TOWN / "towers.csv", TOWN / "assess.toml"
    rows = command_inventory(cli, towers, assess, tmp_path / "out")
    table = rocking.inventory(towers, assess)
    assert len(rows) == 12
    assert_table_is_csv(table, rows)
    for name in ("lon", "lat", "zeta_E", "SLV_linear_kinematic_zeta_E"):
        assert table[name].dtype == np.float64, name
    # The governing ζ_E is the worse of SLV's and SLC's by the most refined method
    # computed, here the non-linear kinematic one (without records); the linear
    # check and SLD's activation are information (worked out here from the columns).
    checks = ["SLV_nonlinear_kinematic_zeta_E", "SLC_nonlinear_kinematic_zeta_E"]
    least = np.min(np.vstack([table[c] for c in checks]), axis=0)
    np.testing.assert_array_equal(table["zeta_E"], least)


def test_bad_rows_get_the_commands_errors_and_the_others_are_right(cli: Path, tmp_path: Path) -> None:
    assess = tmp_path / "town.toml"
    assess.write_text(
        f"[tower]\nwidth = 4.5\nheight = 24.0\nmass = 4.0e5\n\n[site]\nsoil = \"B\"\ngrid = '{GRID}'\nlon = 14.33\nlat = 41.07\nCU = 1.5\n\n"
        "[assessment]\nconfidence_factor = 1.35\n"
    )
    towers = tmp_path / "towers.csv"
    towers.write_text(
        "id,name,lon,lat,tower.width,tower.height,soil\n"
        "A,good,14.34,41.06,5.0,30.0,\n"
        "B,negative width,14.35,41.07,-4.0,30.0,\n"
        "C,outside the grid,13.90,41.07,5.0,30.0,\n"
        "D,not a number,14.36,41.08,5.0,tall,\n"
        "A,the same id,14.37,41.09,5.0,30.0,\n"
        "E,no lon,,41.09,5.0,30.0,\n"
        "F,good on C,14.41,41.10,4.0,20.0,C\n"
    )
    rows = command_inventory(cli, towers, assess, tmp_path / "out", status=1)
    table = rocking.inventory(towers, assess, threads=2)
    assert_table_is_csv(table, rows)
    assert [bool(e) for e in table["error"]] == [False, True, True, True, True, True, False]
    assert "row 2 (id B), column tower.width" in table["error"][1]


def test_a_record_set_gives_the_commands_dynamic_checks(cli: Path, tmp_path: Path) -> None:
    # Three records (the fewest a set may have) and a coarse λ scan: the checks in full, with fewer runs.
    assess = tmp_path / "town.toml"
    assess.write_text(
        f"[tower]\nwidth = 4.5\nheight = 24.0\nmass = 4.0e5\n\n[site]\nsoil = \"B\"\ngrid = '{GRID}'\nlon = 14.33\nlat = 41.07\nCU = 1.5\n\n"
        f"[assessment]\nconfidence_factor = 1.35\nrecords = ['{RECORDS}/kt_01.AT2', '{RECORDS}/kt_02.AT2', '{RECORDS}/kt_03.AT2']\n"
        "lambda = { from = 0.5, to = 3.0, step = 0.5 }\n"
    )
    towers = tmp_path / "towers.csv"
    towers.write_text("id,name,lon,lat,tower.width,tower.height,soil\nA,slender,14.34,41.06,3.6,30.0,\nB,stocky on C,14.41,41.10,5.0,20.0,C\n")
    rows = command_inventory(cli, towers, assess, tmp_path / "out")
    table = rocking.inventory(towers, assess)
    assert "SLC_nonlinear_dynamic_zeta_E" in table
    assert not np.isnan(table["SLC_nonlinear_dynamic_zeta_E"]).any()
    assert_table_is_csv(table, rows)


def test_an_assessment_dict_gives_the_files_numbers() -> None:
    # The example's assess.toml as a dict (on the official grid, as the file is).
    d = {
        "name": "a bell tower of the town",
        "tower": {"width": 4.5, "height": 24.0, "mass": 4.0e5},
        "site": {"code": "ntc2018", "soil": "B", "topography": "T1", "grid": "ntc2018", "lon": 14.33, "lat": 41.07, "VN": 50, "CU": 1.5},
        "assessment": {"confidence_factor": 1.35, "q": 2.0, "capacity": "linear"},
    }
    from_dict = rocking.inventory(TOWN / "towers.csv", d)
    from_file = rocking.inventory(TOWN / "towers.csv", TOWN / "assess.toml")
    assert list(from_dict) == list(from_file)
    for name in from_file:
        np.testing.assert_array_equal(from_dict[name], from_file[name], err_msg=name)


def test_a_bad_header_is_one_line_naming_the_file_and_the_column(tmp_path: Path) -> None:
    towers = tmp_path / "towers.csv"
    towers.write_text("id,name,lon,lat,height\nA,,14.34,41.06,30\n")
    with pytest.raises(ValueError, match=r'towers\.csv: unknown column "height"'):
        rocking.inventory(towers, TOWN / "assess.toml")

"""The town tab against `rocking inventory`: the example town's towers
(chosen with the file picker) give the command's inventory.csv byte for byte,
and the ranking and the ζ_E on the page are its rows sorted by ζ_E; with three
record files the dynamic checks run in the worker, a tower at a time with the
progress told, and give the command's rows with the records as files."""

import csv
import io
import subprocess

from conftest import BIN, OUT, ROOT
from playwright.sync_api import expect

TOWN = ROOT / "examples" / "town"
RECORDS = [ROOT / "data" / "records" / "synthetic" / f"kt_0{k}.AT2" for k in (1, 2, 3)]


def command_csv(towers, assess, out):
    """The text of `rocking inventory`'s inventory.csv."""
    subprocess.run([BIN, "inventory", str(towers), "--assess", str(assess), "--out", str(out)], check=True, capture_output=True)
    return (out / "inventory.csv").read_text()


def town_done(page, timeout=30_000):
    expect(page.locator("#town")).to_have_attribute("data-state", "done", timeout=timeout)
    expect(page.locator("#town-error")).to_be_hidden()
    return page.evaluate("document.getElementById('town').town"), page.evaluate("document.getElementById('town').csv")


def test_the_example_town_is_the_commands_inventory(page, tmp_path):
    page.click("#tab-town")
    expect(page.locator("#town")).to_be_visible()
    expect(page.locator("#results")).to_be_hidden()
    page.set_input_files("#town-towers-file", str(TOWN / "towers.csv"))
    town, text = town_done(page)
    expected = command_csv(TOWN / "towers.csv", TOWN / "assess.toml", tmp_path / "out")
    # Byte for byte (no row has an error, the only place a file's name appears).
    assert text == expected
    rows = list(csv.DictReader(io.StringIO(expected)))
    # Each tower's ζ_E on the page is the command's, to the bit (JSON and CSV
    # both hold the shortest text that reads back to the same double).
    for tower, row in zip(town["towers"], rows):
        assert tower["id"] == row["id"]
        assert tower["zeta_E"] == float(row["zeta_E"])
        assert tower["governing"] == row["governing"]
    # The ranking: the command's rows sorted by ζ_E, shown in that order in the table.
    order = sorted(range(len(rows)), key=lambda i: float(rows[i]["zeta_E"]))
    assert town["ranking"] == order
    shown = page.locator("#town-ranking tbody tr").evaluate_all("rs => rs.map(r => r.dataset.id)")
    assert shown == [rows[i]["id"] for i in order]
    # A tower whose verdict fails (ζ_E < 1) is marked so in the table, and only those.
    failing = sum(float(r["zeta_E"]) < 1 for r in rows)
    assert page.locator("#town-ranking tbody tr td.fails").count() == failing
    # The map's colour bar spans 0 to the largest ζ_E, within [1.2, 3].
    top = max(float(r["zeta_E"]) for r in rows)
    assert float(page.locator("#town-map").get_attribute("data-colour-top")) == min(3.0, max(1.2, top))
    OUT.mkdir(parents=True, exist_ok=True)
    page.locator("#town").screenshot(path=str(OUT / "town.png"))


def test_the_dynamic_checks_in_the_worker_are_the_commands(page, tmp_path):
    page.click("#tab-town")
    lines = (TOWN / "towers.csv").read_text().splitlines()
    towers = tmp_path / "two.csv"
    towers.write_text("\n".join(lines[:3]) + "\n")
    page.set_input_files("#town-towers-file", str(towers))
    town_done(page)
    page.set_input_files("#town-records-file", [str(r) for r in RECORDS])
    expect(page.locator("#town-dynamic")).to_be_enabled()
    page.click("#town-dynamic")
    town, text = town_done(page, timeout=120_000)
    # One tower at a time: the first was told before the second ended.
    assert page.locator("#town").get_attribute("data-progress") == "1"
    # The command with the same set as files, the grid at its place in the repository.
    assess = (TOWN / "assess.toml").read_text().replace('"../../data/', f'"{ROOT}/data/')
    assess = assess.replace("q = 2.0", "q = 2.0\nrecords = [" + ", ".join(f"'{r}'" for r in RECORDS) + "]")
    (tmp_path / "assess.toml").write_text(assess)
    expected = command_csv(towers, tmp_path / "assess.toml", tmp_path / "out")
    assert "SLC_nonlinear_dynamic_zeta_E" in expected.splitlines()[0]
    assert text == expected
    assert [t["zeta_E"] for t in town["towers"]] == [float(r["zeta_E"]) for r in csv.DictReader(io.StringIO(expected))]


def test_a_bad_row_is_named_and_the_others_ranked_and_a_bad_header_stops_all(page, tmp_path):
    page.click("#tab-town")
    towers = tmp_path / "bad.csv"
    towers.write_text("id,name,lon,lat,tower.width\nA,good,14.34,41.06,5.0\nB,negative,14.35,41.07,-4.0\n")
    page.set_input_files("#town-towers-file", str(towers))
    expect(page.locator("#town")).to_have_attribute("data-state", "done", timeout=30_000)
    # The command's line for the bad row, naming the file as chosen, its row and column.
    expect(page.locator("#town-error")).to_contain_text('bad.csv row 2 (id B), column tower.width ("-4.0"): must be a finite number > 0, got -4')
    assert page.locator("#town-ranking tbody tr").evaluate_all("rs => rs.map(r => r.dataset.id)") == ["A"]
    header = tmp_path / "header.csv"
    header.write_text("id,name,lon,lat,height\nA,good,14.34,41.06,30\n")
    page.set_input_files("#town-towers-file", str(header))
    expect(page.locator("#town-error")).to_contain_text('header.csv: unknown column "height"', timeout=30_000)
    expect(page.locator("#town-ranking tbody tr")).to_have_count(0)


def test_cancel_stops_the_dynamic_checks_and_keeps_the_kinematic_ones(page):
    page.click("#tab-town")
    page.click("#town-example")
    kinematic, text = town_done(page)
    assert "dynamic" not in text.splitlines()[0]
    page.set_input_files("#town-records-file", [str(r) for r in RECORDS])
    page.click("#town-dynamic")
    # Cancelled once a tower is told done (on a busy machine a second may be
    # told before the click: at least one, not exactly one), with some of the
    # 12 still to go.
    page.wait_for_function("Number(document.getElementById('town').dataset.progress) >= 1", timeout=120_000)
    page.click("#town-cancel")
    expect(page.locator("#town")).to_have_attribute("data-state", "done")
    expect(page.locator("#town-progress-label")).to_have_text("cancelled")
    expect(page.locator("#town-dynamic")).to_be_enabled()
    assert int(page.locator("#town").get_attribute("data-progress")) < 12
    # The kinematic inventory stays, whole.
    assert page.evaluate("document.getElementById('town').csv") == text
    expect(page.locator("#town-ranking tbody tr")).to_have_count(12)


def test_a_users_own_assessment_file_and_its_grid_give_the_commands_inventory(page, tmp_path):
    """The user's ASSESS.toml and the grid it names, picked: the command's inventory.csv on
    the same files, byte for byte; the records it names are matched to those picked by file
    name, and one not picked is named in one line."""
    mine = tmp_path / "mine"
    (mine / "hazard").mkdir(parents=True)
    grid = mine / "hazard" / "grid.txt"
    grid.write_text((ROOT / "data" / "hazard" / "synthetic_grid.txt").read_text())
    assess = (TOWN / "assess.toml").read_text()
    assert 'grid = "ntc2018"' in assess
    # Heavier than the example's (so not its rows), on a grid file of the user's at its own place.
    assess = assess.replace('grid = "ntc2018"', 'grid = "hazard/grid.txt"').replace("q = 2.0", "q = 1.5")
    (mine / "ASSESS.toml").write_text(assess)
    page.click("#tab-town")
    page.set_input_files("#town-towers-file", str(TOWN / "towers.csv"))
    town_done(page)
    page.set_input_files("#town-assess-file", str(mine / "ASSESS.toml"))
    # The grid it names is not picked yet: one line saying which.
    expect(page.locator("#town-error")).to_have_text("ASSESS.toml: site.grid: names grid.txt, which is not picked", timeout=30_000)
    page.set_input_files("#town-grid-file", str(grid))
    town, text = town_done(page)
    expected = command_csv(TOWN / "towers.csv", mine / "ASSESS.toml", tmp_path / "out")
    assert text == expected
    assert text != command_csv(TOWN / "towers.csv", TOWN / "assess.toml", tmp_path / "example")
    # Records the file names, two of its three picked: the third is named.
    named = assess.replace("q = 1.5", "q = 1.5\nrecords = ['records/kt_01.AT2', 'records/kt_02.AT2', 'records/kt_03.AT2']")
    (mine / "NAMED.toml").write_text(named)
    page.set_input_files("#town-assess-file", str(mine / "NAMED.toml"))
    expect(page.locator("#town-assess-name")).to_have_text("NAMED.toml")
    town_done(page)
    page.set_input_files("#town-records-file", [str(r) for r in RECORDS[:2]])
    page.click("#town-dynamic")
    expect(page.locator("#town-error")).to_have_text("NAMED.toml: assessment.records: no record file picked for kt_03.AT2", timeout=30_000)

"""scripts/study/tables.py: the convergence table's paired changes and its verdict against issue
13's criterion, on synthetic runs whose changes are known exactly."""

import importlib.util
import pathlib
import statistics

from conftest import SOURCE_DIR

spec = importlib.util.spec_from_file_location("study_tables", SOURCE_DIR / "scripts" / "study" / "tables.py")
tables = importlib.util.module_from_spec(spec)
spec.loader.exec_module(tables)


def write_run(out, speed, seed, thickness, springback, pressure, finished=True):
    run = out / f"v{speed}_s{seed}"
    run.mkdir(parents=True)
    (run / "summary.txt").write_text(
        f"finished = {'true' if finished else 'false'}\nloaded_thickness_um = {thickness}\n"
        f"springback_percent = {springback}\nheld_pressure_MPa = {pressure}\n"
        "loaded_unbalanced_force_ratio = 1e-4\nreleased_unbalanced_force_ratio = 2e-4\n"
        "loaded_inertial_number = 0\nreleased_inertial_number = 0\n"
        f"final_thickness_um = {thickness * (1 + springback / 100)}\nsteps = 1000\nplate_work_pJ = 1e6\n")


def test_verdict_uses_the_two_standard_error_band():
    assert tables.verdict([0.01, -0.01, 0.02, 0.0], 0.2).startswith("met")
    assert tables.verdict([0.5, 0.6, 0.55, 0.45], 0.2).startswith("not met")
    # Mean 0.1 < 0.2, but a spread of 0.5 leaves the band across the limit.
    undecided = tables.verdict([0.6, -0.4, 0.5, -0.3], 0.2)
    assert undecided.startswith("undecided") and "<" in undecided
    assert tables.verdict([0.3], 0.2) == "–"  # one pair decides nothing


def test_convergence_table_pairs_seeds_and_skips_unfinished_runs(tmp_path):
    seeds = ["1", "2", "3", "4"]
    thickness_change = [0.1, -0.1, 0.05, 0.0]  # % from 0.05 to 0.025
    for seed, change in zip(seeds, thickness_change):
        write_run(tmp_path, "0.05", seed, 80.0, 5.0, 300.0)
        write_run(tmp_path, "0.025", seed, 80.0 * (1 + change / 100), 5.5, 298.5)
    write_run(tmp_path, "0.05", "5", 80.0, 5.0, 300.0)
    write_run(tmp_path, "0.025", "5", 10.0, 9.0, 1.0, finished=False)  # not a pair
    _, lines = tables.convergence(tmp_path, ["0.05", "0.025"], seeds + ["5"], "scenario.toml")
    text = "\n".join(lines)
    row = next(line for line in lines if line.startswith("| 0.025 | 0.05 |"))
    cells = [cell.strip() for cell in row.split("|")]
    assert cells[3] == "4"
    mean, sd = (float(value) for value in cells[4].split(" [")[0].split(" ± "))
    assert abs(mean - statistics.mean(thickness_change)) < 6e-4
    assert abs(sd - statistics.stdev(thickness_change)) < 6e-4
    assert "+0.500 ± 0.000" in row and "-0.500 ± 0.000" in row  # springback points, pressure %
    verdicts = next(line for line in lines if line.startswith("| 0.05 → 0.025 |"))
    cells = [cell.strip() for cell in verdicts.split("|")[3:6]]
    assert cells[0].startswith("met") and cells[1].startswith("not met") and cells[2].startswith("met")
    assert "nan" not in text
    assert sum(line.startswith("| v0.0") for line in lines) == 9  # every finished run listed once

"""Bad input is refused with a clear message (no FE tools needed)."""
import subprocess

import pytest

from ellc_fea.case import CaseError, parse_case

MATERIAL = {"youngs_modulus": 142000.0, "poisson_ratio": 0.25, "yield_stress": 7900.0}


def _case(body_i, body_j=None, protocol=None):
    return {"material": MATERIAL, "body_I": body_i, "body_J": body_j or {"semi_axes": [5, 5, 5]},
            "protocol": protocol or {"waypoints": [0.0, 0.1], "points_per_segment": 4}}


def test_aspect_and_mean_radius_give_semi_axes():
    case = parse_case(_case({"aspect": [1.0, 1.25, 1.25], "mean_radius": 10.0}), "x")
    assert case.body_i.mean_radius == pytest.approx(10.0)
    assert case.body_i.b / case.body_i.a == pytest.approx(1.25)
    assert case.r_hat == pytest.approx(15.0)


def test_relative_waypoints_scale_with_r_hat():
    case = parse_case(_case({"semi_axes": [5, 5, 5]},
                            protocol={"waypoints_relative": [0.0, 0.1, 0.0]}), "x")
    assert case.waypoints == pytest.approx((0.0, 1.0, 0.0))


@pytest.mark.parametrize("aspect", [[1.0, 3.5, 1.0], [1.0, 1.0, 0.25]])
def test_aspect_outside_mesher_range_is_refused(aspect):
    with pytest.raises(CaseError, match=r"outside 1:\[0.3..3.0\]"):
        parse_case(_case({"aspect": aspect, "mean_radius": 5.0}), "x")


def test_twist_is_refused():
    with pytest.raises(CaseError, match="twist_deg"):
        parse_case(_case({"semi_axes": [5, 5, 5], "twist_deg": 30.0}), "x")


def test_cli_refuses_with_exit_code_2(tmp_path, repo):
    path = tmp_path / "bad.toml"
    path.write_text("[material]\nyoungs_modulus = 1.0\npoisson_ratio = 0.25\nyield_stress = 1.0\n"
                    "[body_I]\nsemi_axes = [1.0, 4.0, 1.0]\n[body_J]\nsemi_axes = [1.0, 1.0, 1.0]\n"
                    "[protocol]\nwaypoints = [0.0, 0.1]\n")
    proc = subprocess.run([f"{repo}/fea/run_case", str(path), "--out", str(tmp_path)],
                          capture_output=True, text=True)
    assert proc.returncode == 2
    assert "refused" in proc.stderr and "1:4" in proc.stderr


@pytest.mark.parametrize("slope", ["0", "-1e7", "nan", "inf"])
def test_cli_refuses_a_contact_slope_that_is_not_a_positive_number(tmp_path, repo, slope):
    path = tmp_path / "ok.toml"
    path.write_text("[material]\nyoungs_modulus = 1.0\npoisson_ratio = 0.25\nyield_stress = 1.0\n"
                    "[body_I]\nsemi_axes = [1.0, 1.0, 1.0]\n[body_J]\nsemi_axes = [1.0, 1.0, 1.0]\n"
                    "[protocol]\nwaypoints = [0.0, 0.1]\n")
    proc = subprocess.run([f"{repo}/fea/run_case", str(path), "--out", str(tmp_path), f"--contact-slope={slope}"],
                          capture_output=True, text=True)
    assert proc.returncode == 2
    assert "--contact-slope" in proc.stderr and "positive, finite" in proc.stderr


def test_deck_carries_the_contact_slope_and_reports_it(tmp_path, needs_fe_tools):
    from ellc_fea.deck import CONTACT_SLOPE, write_deck
    from ellc_fea.mesh import build_mesh
    case = parse_case(_case({"semi_axes": [5, 5, 5]}), "x")
    mesh = build_mesh(case.body_i, case.body_j, "coarse")
    for slope in (None, 7.0e7):
        deck = tmp_path / "x.inp"
        summary = write_deck(str(deck), case, mesh) if slope is None else write_deck(str(deck), case, mesh,
                                                                                      contact_slope=slope)
        lines = deck.read_text().splitlines()
        written = float(lines[lines.index("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR") + 1])
        assert written == summary["contact_slope"] == (CONTACT_SLOPE if slope is None else slope)

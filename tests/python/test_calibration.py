"""Calibration recovers known constants from synthetic data made by the law itself with 1 % noise,
and fails clearly on elastic data. Python API and `ellc fit` give the same result.

Stated tolerances (1 % Gaussian force noise, 6 geometries with R_e/r^ = 0.10..0.63, 40 loading
points each up to 1.5 delta_max, seed 0; the worst of 20 seeds is in parentheses):
  lambda_max(R_e/r^) of eq. (52) over the data range    1.5 %   (0.6 %)
  epsilon_max(R_e/r^) of eq. (52) over the data range   8 %     (6.2 %)
  n                                                     15 %    (12 %)
  m, o, p                                               10 %    (2.3, 8.2, 1.9 %)
  s, t, u                                               15 %    (10, 6.9, 6.9 %)
  RMS relative force error of the calibrated law        1.5 %   (1.2 %; the noise is 1 %)
  per case, with the shared n: lambda_max 1.5 % (0.6 %), epsilon_max 8 % (6.7 %)
Without noise every constant comes back within 0.1 %.
"""

import tomllib

import numpy as np
import pytest

import ellc
from conftest import GEOMETRIES, TRUE_FIT, body, case_toml, run_cli, synthetic_cases

RADIUS_RANGE = np.linspace(0.10, 0.63, 60)


def relative_error(fit, key):
    return abs(getattr(fit, key) / TRUE_FIT[key] - 1.0)


@pytest.fixture(scope="module")
def noisy_result():
    return ellc.calibrate(synthetic_cases(noise=0.01, seed=0))


def test_recovers_eq52_functions_with_one_percent_noise(noisy_result):
    true = ellc.TransitionFit(**TRUE_FIT)
    fit = noisy_result.fit
    assert noisy_result.rates_fitted and noisy_result.amplitudes_fitted
    assert np.max(np.abs(fit.lambda_max(RADIUS_RANGE) / true.lambda_max(RADIUS_RANGE) - 1)) < 0.015
    assert np.max(np.abs(fit.epsilon_max(RADIUS_RANGE) / true.epsilon_max(RADIUS_RANGE) - 1)) < 0.08
    assert relative_error(fit, "n") < 0.15


def test_recovers_constants_with_one_percent_noise(noisy_result):
    for key in "mop":
        assert relative_error(noisy_result.fit, key) < 0.10, key
    for key in "stu":
        assert relative_error(noisy_result.fit, key) < 0.15, key
    for case in noisy_result.cases:
        assert case.plateau_reached
        assert case.model_rms < 0.015, case.name


def test_per_case_fits_match_the_true_law(noisy_result):
    true = ellc.TransitionFit(**TRUE_FIT)
    for case in noisy_result.cases:
        # With the shared n (step 2); a case's own n trades off against its epsilon_max (up to 15 %).
        assert case.shared.lambda_max == pytest.approx(true.lambda_max(case.radius_ratio), rel=0.015)
        assert case.shared.epsilon_max == pytest.approx(true.epsilon_max(case.radius_ratio), rel=0.08)
        assert case.own.lambda_max == pytest.approx(true.lambda_max(case.radius_ratio), rel=0.03)
        profile = case.profile
        assert set(profile) == {"overlap", "force", "contact_radius_ratio", "lambda", "weight"}
        assert np.all(profile["overlap"] > case.yield_overlap)


def test_noise_free_data_gives_the_constants_back():
    result = ellc.calibrate(synthetic_cases(noise=0.0))
    for key in TRUE_FIT:
        assert relative_error(result.fit, key) < 1e-3, key


def test_unloading_points_are_ignored():
    clean = synthetic_cases(noise=0.0, names=["sphere", "flat", "slim"])
    with_unloading = []
    for case in clean:
        contact = ellc.Contact.between(case.body_i, case.body_j, law=ellc.LawParameters(ellc.TransitionFit(**TRUE_FIT)))
        peak = case.overlaps[-1]
        path = np.concatenate([case.overlaps[:20], np.linspace(case.overlaps[19], 0.0, 10), case.overlaps[20:]])
        with_unloading.append(ellc.CalibrationCase(case.name, case.body_i, case.body_j, path, contact.force(path)))
        assert path.max() == peak
    a, b = ellc.calibrate(clean).fit, ellc.calibrate(with_unloading).fit
    for key in TRUE_FIT:
        assert getattr(a, key) == pytest.approx(getattr(b, key), rel=1e-9)


def test_elastic_data_below_the_yield_point_fails_clearly():
    body_i, body_j = body(GEOMETRIES["sphere"][0]), body(GEOMETRIES["sphere"][1])
    contact = ellc.Contact.between(body_i, body_j)
    overlaps = np.linspace(0.01, 0.9 * contact.constants.yield_overlap, 20)
    case = ellc.CalibrationCase("elastic", body_i, body_j, overlaps, contact.force(overlaps))
    with pytest.raises(ValueError, match=r"elastic: the data never leaves the elastic regime: its largest overlap"):
        ellc.calibrate([case])


def test_hertz_data_beyond_the_yield_point_fails_clearly():
    body_i, body_j = body(GEOMETRIES["paper_case2"][0]), body(GEOMETRIES["paper_case2"][1])
    constants = ellc.Contact.between(body_i, body_j).constants
    overlaps = np.linspace(0.05, 8.0 * constants.yield_overlap, 40)
    hertz = constants.hertz_coefficient * overlaps ** 1.5  # an elastic material: Hertz throughout
    case = ellc.CalibrationCase("hertz", body_i, body_j, overlaps, hertz * (1 + 0.005 * np.sin(overlaps)))
    with pytest.raises(ellc.InputError, match=r"hertz: the data never leaves the elastic regime: beyond delta_Y"):
        ellc.calibrate([case])


def test_plastic_data_close_to_hertz_is_not_mistaken_for_elastic():
    # Loaded to 4 delta_Y only, the law is within ~1.4 % of Hertz: still plastic data.
    body_i = body(GEOMETRIES["sphere"][0])
    contact = ellc.Contact.between(body_i, body_i)
    overlaps = np.linspace(0.0, 4.0 * contact.constants.yield_overlap, 41)[1:]
    forces = contact.force(overlaps) * (1 + 0.01 * np.random.default_rng(3).standard_normal(40))
    result = ellc.calibrate([ellc.CalibrationCase("early", body_i, body_i, overlaps, forces)])
    assert 1.6 < result.cases[0].shared.lambda_max < 4.0


def test_fewer_than_four_geometries_keep_the_rates_of_the_prior():
    result = ellc.calibrate(synthetic_cases(noise=0.0, names=["sphere", "slim"]))
    assert not result.rates_fitted and result.amplitudes_fitted
    assert result.fit.o == ellc.TransitionFit().o and result.fit.t == ellc.TransitionFit().t
    assert any("o and t kept from the prior" in warning for warning in result.warnings)


def write_case_files(folder, cases):
    paths = []
    for case in cases:
        csv = folder / f"{case.name}.csv"
        np.savetxt(csv, np.c_[case.overlaps, case.forces], delimiter=",", header="overlap,force", comments="")
        (folder / f"{case.name}.toml").write_text(case_toml(*GEOMETRIES[case.name]))
        paths.append(csv)
    return paths


def test_cli_and_python_give_the_same_model_table(cli, tmp_path, noisy_result):
    paths = write_case_files(tmp_path, synthetic_cases(noise=0.01, seed=0))
    run_cli(cli, "fit", *paths, "-o", tmp_path / "model.toml", "--plot", tmp_path / "fit")
    model = tomllib.loads((tmp_path / "model.toml").read_text())["model"]
    files = ellc.calibrate_files([str(path) for path in paths])
    for key in TRUE_FIT:
        assert model[key] == pytest.approx(getattr(files.fit, key), rel=1e-12), key
        # The CSV round trip (17 digits) changes the data by round-off only.
        assert model[key] == pytest.approx(getattr(noisy_result.fit, key), rel=1e-6), key
    assert tomllib.loads(files.model_toml())["model"] == model
    for suffix in ("_lambda.csv", "_cases.csv", "_radius.csv", "_lambda.png", "_radius.png"):
        assert (tmp_path / f"fit{suffix}").stat().st_size > 0


def test_calibrated_table_runs_in_ellc_curve(cli, tmp_path, noisy_result):
    case = (case_toml(*GEOMETRIES["paper_case2"]) + "[protocol]\nwaypoints_relative = [0.0, 0.10, 0.0]\n"
            + "points_per_segment = 20\n" + noisy_result.model_toml())
    (tmp_path / "calibrated.toml").write_text(case)
    run_cli(cli, "curve", tmp_path / "calibrated.toml", "-o", tmp_path / "curve.csv")
    table = np.genfromtxt(tmp_path / "curve.csv", delimiter=",", names=True, dtype=None, encoding="utf-8")
    expected = ellc.Contact.between(body(GEOMETRIES["paper_case2"][0]), body(GEOMETRIES["paper_case2"][1]),
                                    law=noisy_result.law).force(table["overlap"])
    np.testing.assert_allclose(table["force"], expected, rtol=1e-12)


def test_cli_rejects_elastic_data_with_exit_code_2(cli, tmp_path):
    body_i, body_j = body(GEOMETRIES["sphere"][0]), body(GEOMETRIES["sphere"][1])
    contact = ellc.Contact.between(body_i, body_j)
    overlaps = np.linspace(0.01, 0.9 * contact.constants.yield_overlap, 10)
    np.savetxt(tmp_path / "elastic.csv", np.c_[overlaps, contact.force(overlaps)], delimiter=",",
               header="overlap,force", comments="")
    (tmp_path / "spheres.toml").write_text(case_toml(*GEOMETRIES["sphere"]))
    completed = run_cli(cli, "fit", f"{tmp_path / 'elastic.csv'}:{tmp_path / 'spheres.toml'}", check=False)
    assert completed.returncode == 2
    assert "never leaves the elastic regime" in completed.stderr
    assert "delta_Y" in completed.stderr


def test_cli_data_errors_name_the_file_and_line(cli, tmp_path):
    (tmp_path / "a.csv").write_text("overlap,force\n0.1,1.0\n0.2,oops\n")
    (tmp_path / "a.toml").write_text(case_toml(*GEOMETRIES["sphere"]))
    completed = run_cli(cli, "fit", tmp_path / "a.csv", check=False)
    assert completed.returncode == 2 and "a.csv:3" in completed.stderr and "force" in completed.stderr
    (tmp_path / "b.csv").write_text("delta,F\n0.1,1.0\n")
    completed = run_cli(cli, "fit", tmp_path / "b.csv", check=False)
    assert completed.returncode == 2 and "overlap and force" in completed.stderr
    (tmp_path / "c.csv").write_text("overlap,force\n0.1,1.0\n")
    completed = run_cli(cli, "fit", tmp_path / "c.csv", check=False)
    assert completed.returncode == 2 and "c.toml" in completed.stderr


def test_case_comment_line_names_the_geometry(tmp_path):
    (tmp_path / "geometry.toml").write_text(case_toml(*GEOMETRIES["flat"]))
    (tmp_path / "run.csv").write_text("# case = geometry.toml\noverlap,force,segment\n0.1,5.0,1\n0.2,9.0,1\n")
    case = ellc.read_calibration_case(str(tmp_path / "run.csv"))
    assert case.name == "run" and case.body_i.semi_axes[1] == pytest.approx(2 * case.body_i.semi_axes[0])
    np.testing.assert_array_equal(case.forces, [5.0, 9.0])

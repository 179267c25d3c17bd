"""The bindings give the same numbers as the C++ CLI (`ellc curve`) on the paper's cases."""

import numpy as np
import pytest

import ellc
from conftest import SOURCE_DIR, run_cli

RTOL = 1e-12  # the same library calls: equal to round-off (the CSV carries 17 digits)


def equal_volume_sphere(body):
    return ellc.Body(np.full(3, body.mean_radius), body.material)


@pytest.fixture(scope="module", params=["paper_case2.toml", "paper_case1.toml"])
def case_and_csv(request, cli, tmp_path_factory):
    case_path = SOURCE_DIR / "examples" / request.param
    csv_path = tmp_path_factory.mktemp("curve") / "curve.csv"
    run_cli(cli, "curve", case_path, "-o", csv_path)
    table = np.genfromtxt(csv_path, delimiter=",", names=True, dtype=None, encoding="utf-8")
    return ellc.read_curve_case(str(case_path)), table


def test_path_is_the_cli_path(case_and_csv):
    case, table = case_and_csv
    np.testing.assert_array_equal(case.overlap_path(), table["overlap"])


def test_force_history_and_regime_match(case_and_csv):
    case, table = case_and_csv
    contact = ellc.Contact.from_case(case)
    result = contact.evaluate_path(case.overlap_path())
    np.testing.assert_allclose(result.force, table["force"], rtol=RTOL, atol=0)
    np.testing.assert_allclose(result.max_overlap, table["max_overlap"], rtol=RTOL, atol=0)
    np.testing.assert_allclose(result.plastic_overlap, table["plastic_overlap"], rtol=RTOL, atol=1e-15)
    assert [ellc.regime_name(int(code)) for code in result.regime] == list(table["regime"])
    assert set(result.regime) >= {int(ellc.Regime.ELASTIC_PLASTIC), int(ellc.Regime.UNLOADING)}


def test_normalized_columns_and_comparison_curves_match(case_and_csv):
    case, table = case_and_csv
    contact = ellc.Contact.from_case(case)
    constants = contact.constants
    path = case.overlap_path()
    np.testing.assert_allclose(path / constants.yield_overlap, table["overlap_over_yield"], rtol=RTOL)
    np.testing.assert_allclose(contact.force(path) / constants.yield_force, table["force_over_yield"], rtol=RTOL)
    spheres = ellc.Contact.between(equal_volume_sphere(case.body_i), equal_volume_sphere(case.body_j),
                                   hertz=case.model.hertz, law=case.model.law)
    np.testing.assert_allclose(spheres.force(path) / constants.yield_force,
                               table["force_equal_volume_spheres_over_yield"], rtol=RTOL)
    thornton = ellc.Contact.between(case.body_i, case.body_j, hertz=case.model.hertz,
                                    law=case.model.law.elastic_fully_plastic())
    np.testing.assert_allclose(thornton.force(path) / constants.yield_force,
                               table["force_elastic_fully_plastic_over_yield"], rtol=RTOL)


def test_contact_patches_match(case_and_csv):
    case, table = case_and_csv
    patches = ellc.Contact.from_case(case).patches(case.overlap_path())
    np.testing.assert_allclose(patches.semi_axis_major, table["contact_semi_axis_major"], rtol=RTOL, atol=1e-15)
    np.testing.assert_allclose(patches.semi_axis_minor, table["contact_semi_axis_minor"], rtol=RTOL, atol=1e-15)
    np.testing.assert_allclose(patches.peak_pressure, table["peak_pressure"], rtol=RTOL, atol=1e-12)


def test_scalar_api_agrees_with_batch(case_and_csv):
    case, _ = case_and_csv
    contact = ellc.Contact.from_case(case)
    path = case.overlap_path()
    batch = contact.evaluate_path(path)
    history = 0.0
    for index in range(0, path.size, 37):
        history = batch.max_overlap[index - 1] if index else 0.0
        single = ellc.evaluate_contact(contact.constants, path[index], history)
        assert single.force == batch.force[index]
        assert int(single.regime) == int(batch.regime[index])


def test_path_can_be_continued_from_its_history(case_and_csv):
    case, _ = case_and_csv
    contact = ellc.Contact.from_case(case)
    path = case.overlap_path()
    whole = contact.evaluate_path(path)
    half = path.size // 2
    first = contact.evaluate_path(path[:half])
    second = contact.evaluate_path(path[half:], initial_max_overlap=first.max_overlap[-1])
    np.testing.assert_array_equal(np.concatenate([first.force, second.force]), whole.force)


def test_hertz_layer_matches_the_constants(case_and_csv):
    case, _ = case_and_csv
    constants = ellc.Contact.from_case(case).constants
    tip = ellc.tip_contact(ellc.TipBody(case.body_i.semi_axes, case.body_i.twist),
                           ellc.TipBody(case.body_j.semi_axes, case.body_j.twist))
    shape = ellc.hertz_shape(ellc.relative_curvature(tip.body_i, tip.body_j, tip.alpha), case.model.hertz)
    assert shape.equivalent_radius == pytest.approx(constants.equivalent_radius, rel=1e-14)
    hertz = ellc.hertz_contact(shape, constants.effective_modulus, constants.yield_overlap)
    assert hertz.force == pytest.approx(constants.yield_force, rel=1e-12)
    assert hertz.peak_pressure == pytest.approx(constants.yield_pressure, rel=1e-12)
    rebuilt = ellc.make_contact_constants(ellc.mix(case.body_i.material, case.body_j.material), tip.body_i,
                                          tip.body_j, tip.alpha, case.body_i.mean_radius + case.body_j.mean_radius,
                                          hertz=case.model.hertz, law=case.model.law)
    assert rebuilt.plastic_limit_overlap == constants.plastic_limit_overlap


def test_exact_hertz_mode_matches_the_cli(cli, tmp_path):
    case_path = SOURCE_DIR / "examples" / "paper_case1.toml"
    run_cli(cli, "curve", case_path, "-o", tmp_path / "exact.csv", "--hertz", "exact")
    table = np.genfromtxt(tmp_path / "exact.csv", delimiter=",", names=True, dtype=None, encoding="utf-8")
    case = ellc.read_curve_case(str(case_path))
    case.model.hertz = "exact"
    contact = ellc.Contact.from_case(case)
    np.testing.assert_allclose(contact.force(case.overlap_path()), table["force"], rtol=RTOL, atol=0)
    hale = ellc.Contact.between(case.body_i, case.body_j, hertz="hale")
    assert contact.constants.f1 != hale.constants.f1  # the mode really changed

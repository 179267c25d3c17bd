"""numpy input validation: wrong shape or dtype raises a clear ValueError."""

import numpy as np
import pytest

import ellc
from conftest import GEOMETRIES, body


@pytest.fixture(scope="module")
def contact():
    return ellc.Contact.between(body(GEOMETRIES["sphere"][0]), body(GEOMETRIES["sphere"][1]))


@pytest.mark.parametrize("bad, message", [
    (np.zeros((3, 2)), r"overlaps: expected a 1-D array, got shape \(3, 2\)"),
    (np.float64(0.5), r"overlaps: expected a 1-D array, got shape \(\)"),
    (np.array([0.1, 0.2], dtype=complex), r"overlaps: expected a real numeric dtype \(float64\), got dtype\('complex128'\)"),
    (np.array([True, False]), r"overlaps: expected a real numeric dtype"),
    (np.array(["0.1", "0.2"]), r"overlaps: expected a real numeric dtype"),
    (np.array([0.1, None], dtype=object), r"overlaps: expected a real numeric dtype"),
])
def test_bad_overlaps_raise_value_error(contact, bad, message):
    for method in (contact.evaluate_path, contact.loading_force, contact.patches, contact.force):
        with pytest.raises(ValueError, match=message):
            method(bad)


def test_lists_integers_float32_and_strided_views_are_accepted(contact):
    reference = contact.force(np.array([0.0, 1.0, 2.0, 3.0]))
    np.testing.assert_array_equal(contact.force([0.0, 1.0, 2.0, 3.0]), reference)
    np.testing.assert_array_equal(contact.force(np.arange(4)), reference)
    np.testing.assert_array_equal(contact.force(np.arange(4, dtype=np.float32)), reference)
    strided = np.arange(8, dtype=float)[::2] / 2.0  # non-contiguous view of 0, 1, 2, 3
    np.testing.assert_array_equal(contact.force(strided), reference)


def test_outputs_are_numpy_arrays_of_the_input_length(contact):
    result = contact.evaluate_path(np.linspace(0.0, 2.0, 7))
    for array, dtype in ((result.force, np.float64), (result.max_overlap, np.float64),
                         (result.plastic_overlap, np.float64), (result.regime, np.uint8)):
        assert isinstance(array, np.ndarray) and array.shape == (7,) and array.dtype == dtype


def test_mismatched_lengths_and_bad_options():
    body_i = body(GEOMETRIES["sphere"][0])
    with pytest.raises(ValueError, match=r"forces: expected the same length as overlaps \(3\), got 2"):
        ellc.CalibrationCase("x", body_i, body_i, [0.1, 0.2, 0.3], [1.0, 2.0])
    with pytest.raises(ValueError, match=r"forces: expected a 1-D array"):
        ellc.CalibrationCase("x", body_i, body_i, [0.1, 0.2], [[1.0, 2.0]])
    with pytest.raises(ValueError, match=r"y: expected the same length as x"):
        ellc.hertz_pressure(1.0, 0.5, 1.0, [0.0, 0.1], [0.0])
    with pytest.raises(ValueError, match=r"hertz = 'halle': expected 'hale' or 'exact'"):
        ellc.Contact.between(body_i, body_i, hertz="halle")
    with pytest.raises(ValueError, match=r"semi_axes"):
        ellc.Body([1.0, -1.0, 1.0], body_i.material)
    with pytest.raises(ValueError, match=r"poisson_ratio"):
        ellc.Material(youngs_modulus=1.0, poisson_ratio=0.7, yield_stress=1.0)
    with pytest.raises(ValueError, match=r"model.n"):
        ellc.LawParameters(ellc.TransitionFit(n=-1.0))


def test_bad_case_file_raises_input_error_a_value_error(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text("[material]\nyoungs_modulus = -1\npoisson_ratio = 0.25\nyield_stress = 1\n")
    with pytest.raises(ellc.InputError, match="youngs_modulus"):
        ellc.read_curve_case(str(path))
    assert issubclass(ellc.InputError, ValueError)


def test_vectorized_helpers(contact):
    x = np.linspace(-1.0, 1.0, 5)
    pressure = ellc.hertz_pressure(1.0, 0.5, 2.0, x, np.zeros(5))
    np.testing.assert_allclose(pressure, 2.0 * np.sqrt(1.0 - x ** 2), atol=1e-15)
    fit = ellc.TransitionFit()
    np.testing.assert_allclose(fit.lambda_max(np.array([0.0, 0.25])), [1.05 + 2.42, 1.05 * np.exp(-4.62 / 4) + 2.42])
    constants = contact.constants
    shape = ellc.HertzShape()
    shape.equivalent_radius, shape.f1, shape.f2 = constants.equivalent_radius, constants.f1, constants.f2
    hertz = ellc.hertz_contacts(shape, constants.effective_modulus, [constants.yield_overlap, 0.5])
    assert hertz["force"][0] == pytest.approx(constants.yield_force, rel=1e-12)
    assert hertz["peak_pressure"][0] == pytest.approx(constants.yield_pressure, rel=1e-12)
    with pytest.raises(ValueError, match="overlaps: expected a 1-D array"):
        ellc.hertz_contacts(shape, constants.effective_modulus, [[0.1]])
    profile = contact.lambda_profile([0.1, 1.0, 10.0])
    assert np.isnan(profile[0]) and profile[2] == pytest.approx(contact.constants.lambda_max)


def test_batch_calls_run_concurrently_in_threads(contact):
    """The batch loops release the GIL; threads must still get exactly the serial results."""
    from concurrent.futures import ThreadPoolExecutor

    paths = [np.linspace(0.0, 0.5 + index, 20000) for index in range(8)]
    serial = [contact.evaluate_path(path).force for path in paths]
    with ThreadPoolExecutor(max_workers=4) as pool:
        threaded = list(pool.map(lambda path: contact.evaluate_path(path).force, paths))
    for expected, got in zip(serial, threaded):
        np.testing.assert_array_equal(got, expected)

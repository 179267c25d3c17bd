"""Posed ellipsoids and the narrow phase from Python: a tip-to-tip pose gives the numbers of the
tip geometry (and so of `ellc curve`)."""

import numpy as np
import pytest

import ellc
from conftest import GEOMETRIES, body


def quaternion_about_z(angle):
    return [np.cos(angle / 2), 0.0, 0.0, np.sin(angle / 2)]


@pytest.mark.parametrize("name", ["paper_case2", "mixed", "sphere"])
def test_tip_pose_matches_the_tip_contact_force(name):
    body_i, body_j = body(GEOMETRIES[name][0]), body(GEOMETRIES[name][1])
    contact = ellc.Contact.between(body_i, body_j)
    material = ellc.mix(body_i.material, body_j.material)
    history = 0.0
    for overlap in (0.2, 1.0, 2.0, 1.5):
        centre_j = body_i.semi_axes[0] + body_j.semi_axes[0] - overlap
        narrow = ellc.ellipsoid_contact(ellc.Ellipsoid(body_i.semi_axes),
                                        ellc.Ellipsoid(body_j.semi_axes, ellc.Pose([centre_j, 0.0, 0.0])))
        assert narrow.status == ellc.NarrowPhaseStatus.CONTACT
        assert narrow.geometry.overlap == pytest.approx(overlap, rel=1e-9)
        np.testing.assert_allclose(narrow.geometry.normal, [1.0, 0.0, 0.0], atol=1e-12)
        normal = ellc.normal_contact(narrow.geometry, material, body_i.mean_radius + body_j.mean_radius,
                                     max_overlap=history)
        expected = ellc.evaluate_contact(contact.constants, narrow.geometry.overlap, history)
        assert normal.law.force == pytest.approx(expected.force, rel=1e-9)
        assert normal.force_on_j[0] == pytest.approx(expected.force, rel=1e-9)
        history = normal.law.max_overlap


def test_separated_rotated_pair_and_warm_start():
    body_i = ellc.Ellipsoid([2.0, 1.0, 1.0])
    far = ellc.Ellipsoid([2.0, 1.0, 1.0], ellc.Pose([0.0, 3.0, 0.0], quaternion_about_z(np.pi / 2)))
    result = ellc.ellipsoid_contact(body_i, far)
    assert result.status == ellc.NarrowPhaseStatus.SEPARATED and result.geometry.overlap <= 0
    near = ellc.Ellipsoid([2.0, 1.0, 1.0], ellc.Pose([0.0, 2.9, 0.0], quaternion_about_z(np.pi / 2)))
    first = ellc.ellipsoid_contact(body_i, near)
    assert first.status == ellc.NarrowPhaseStatus.CONTACT
    assert first.geometry.overlap == pytest.approx(0.1, rel=1e-9)  # 1 (I along y) + 2 (J along y) - 2.9
    again = ellc.ellipsoid_contact(body_i, near, warm_start=first.warm_start)
    assert again.geometry.overlap == pytest.approx(first.geometry.overlap, rel=1e-12)
    assert not again.cold_start
    # A, B (what the law uses) are eq. (5) of the reported sides: here α = 90°.
    g = first.geometry
    eq5 = ellc.relative_curvature(g.curvature_i.principal(), g.curvature_j.principal(), g.alpha)
    assert g.relative.a_sum == pytest.approx(eq5.a_sum, rel=1e-12)
    assert g.relative.b_sum == pytest.approx(eq5.b_sum, rel=1e-12)


def test_wall_contact_and_bad_input():
    sphere = ellc.Ellipsoid([1.0, 1.0, 1.0], ellc.Pose([0.0, 0.0, 0.95]))
    wall = ellc.wall_contact(sphere, ellc.Plane([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]))
    assert wall.status == ellc.NarrowPhaseStatus.CONTACT and wall.geometry.overlap == pytest.approx(0.05)
    assert ellc.wall_mean_radius_sum(sphere) == pytest.approx(2.0)
    with pytest.raises(ValueError, match="semi_axes"):
        ellc.Ellipsoid([1.0, 0.0, 1.0])
    with pytest.raises(ValueError, match="quaternion"):
        ellc.Ellipsoid([1.0, 1.0, 1.0], ellc.Pose([0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0]))

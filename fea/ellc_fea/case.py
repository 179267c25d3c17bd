"""Read and validate a case TOML: [material], [body_I], [body_J], [protocol].

The tables are the ones `ellc curve` reads, so one case file serves both; FE-only settings
(mesh level, elastic material) are command-line flags of fea/run_case.
"""
from __future__ import annotations

import tomllib
from dataclasses import dataclass

ASPECT_MIN, ASPECT_MAX = 0.3, 3.0  # what the mesher is known to handle, relative to a


class CaseError(ValueError):
    """A case the FE pipeline refuses, with a message meant for the user."""


@dataclass(frozen=True)
class Material:
    youngs_modulus: float
    poisson_ratio: float
    yield_stress: float


@dataclass(frozen=True)
class Body:
    a: float
    b: float
    c: float

    @property
    def mean_radius(self) -> float:
        return (self.a * self.b * self.c) ** (1.0 / 3.0)


@dataclass(frozen=True)
class Case:
    name: str
    material: Material
    body_i: Body
    body_j: Body
    waypoints: tuple[float, ...]  # absolute overlaps in micrometre, first one 0
    points_per_segment: int

    @property
    def r_hat(self) -> float:
        """r^{I,J} = r^I + r^J (eq. 50)."""
        return self.body_i.mean_radius + self.body_j.mean_radius


def _body(table: dict, label: str) -> Body:
    if float(table.get("twist_deg", 0.0)) != 0.0:
        raise CaseError(f"[{label}] twist_deg: the FE pipeline models aligned bodies only "
                        "(twist_deg = 0); a twisted pair has no octant symmetry")
    if "semi_axes" in table:
        a, b, c = (float(v) for v in table["semi_axes"])
    elif "aspect" in table and "mean_radius" in table:
        ra, rb, rc = (float(v) for v in table["aspect"])
        scale = float(table["mean_radius"]) / (ra * rb * rc) ** (1.0 / 3.0)
        a, b, c = ra * scale, rb * scale, rc * scale
    else:
        raise CaseError(f"[{label}] needs semi_axes = [a,b,c] or aspect = [..] with mean_radius")
    if min(a, b, c) <= 0.0:
        raise CaseError(f"[{label}] semi-axes must be positive, got {a}, {b}, {c}")
    for name, v in (("b", b), ("c", c)):
        ratio = v / a
        if not ASPECT_MIN <= ratio <= ASPECT_MAX:
            raise CaseError(
                f"[{label}] aspect ratio a:{name} = 1:{ratio:.3g} is outside 1:[{ASPECT_MIN}..{ASPECT_MAX}], "
                "which the FE mesher does not handle; refusing")
    return Body(a, b, c)


def _waypoints(protocol: dict, r_hat: float) -> tuple[float, ...]:
    if "waypoints" in protocol:
        pts = [float(v) for v in protocol["waypoints"]]
    elif "waypoints_relative" in protocol:
        pts = [float(v) * r_hat for v in protocol["waypoints_relative"]]
    else:
        raise CaseError("[protocol] needs waypoints or waypoints_relative")
    if len(pts) < 2 or pts[0] != 0.0:
        raise CaseError("[protocol] needs at least two waypoints, starting at 0")
    if min(pts) < 0.0:
        raise CaseError("[protocol] overlaps must be >= 0")
    if any(p == q for p, q in zip(pts, pts[1:])):
        raise CaseError("[protocol] consecutive waypoints must differ")
    return tuple(pts)


def _material(table: dict) -> Material:
    try:
        m = Material(float(table["youngs_modulus"]), float(table["poisson_ratio"]),
                     float(table["yield_stress"]))
    except KeyError as err:
        raise CaseError(f"[material] missing {err.args[0]}") from None
    if m.youngs_modulus <= 0 or not -1.0 < m.poisson_ratio < 0.5 or m.yield_stress <= 0:
        raise CaseError("[material] needs E > 0, -1 < nu < 0.5, Y > 0")
    return m


def parse_case(data: dict, name: str) -> Case:
    for key in ("material", "body_I", "body_J", "protocol"):
        if key not in data:
            raise CaseError(f"missing table [{key}]")
    body_i, body_j = _body(data["body_I"], "body_I"), _body(data["body_J"], "body_J")
    r_hat = body_i.mean_radius + body_j.mean_radius
    protocol = data["protocol"]
    return Case(name=name, material=_material(data["material"]), body_i=body_i, body_j=body_j,
                waypoints=_waypoints(protocol, r_hat),
                points_per_segment=int(protocol.get("points_per_segment", 20)))


def load_case(path: str) -> Case:
    with open(path, "rb") as fh:
        data = tomllib.load(fh)
    stem = path.rsplit("/", 1)[-1].removesuffix(".toml")
    return parse_case(data, stem)

// The shared contact model (src/ellc/contact/contact_model.hpp, contact_parameters.hpp,
// contact_history.hpp, pair_contact.hpp): each named sub-model against its closed form, the
// parameter vocabulary, the history record's layout, and the balance laws of the pair forces.

#include "ellc/contact/contact_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ellc/contact/contact_force.hpp"
#include "ellc/contact/contact_history.hpp"
#include "ellc/contact/contact_parameters.hpp"
#include "ellc/contact/pair_contact.hpp"
#include "ellc/law/contact_law.hpp"

namespace ellc {
namespace {

const Material kNmc{142000.0, 0.25, 7900.0};

// Constants of two bodies with principal curvatures (κ, κ ratio) against each other, tip to tip.
ContactConstants constants_for(const Material& material, PrincipalCurvatures i, PrincipalCurvatures j) {
  return make_contact_constants(mix(material, material), i, j, 0.0, 10.0, HertzMode::hale);
}

ContactKinematics approaching(double normal_speed, double mass = 2.0) {
  return {Eigen::Vector3d::UnitX(), -normal_speed * Eigen::Vector3d::UnitX(), mass};
}

TEST(ContactModel, NamesRoundTripAndUnknownNamesAreRefused) {
  for (const auto model : {NormalModel::becker_kamlah, NormalModel::hertz})
    EXPECT_EQ(normal_model_named(name_of(model)), model);
  for (const auto model : {DampingModel::contact_radius, DampingModel::hertz_tangent})
    EXPECT_EQ(damping_model_named(name_of(model)), model);
  for (const auto model : {TangentialModel::mindlin, TangentialModel::ratio})
    EXPECT_EQ(tangential_model_named(name_of(model)), model);
  EXPECT_FALSE(normal_model_named("thornton").has_value());
  EXPECT_EQ(damping_model_names(), "contact_radius or hertz_tangent");
}

// For a circular contact (spheres) the Hertz tangent dF/dδ = 2 E_e a exactly, so the two damping
// sub-models are the same dashpot; for an elliptical one they differ by f1/f2 against f2^{-3/2}.
TEST(ContactModel, BothDampingStiffnessesAreTheHertzTangentOnCircularContacts) {
  ContactModel model;
  model.normal_damping = 0.3;
  const double overlap = 0.05;
  const double speed = 0.7;
  auto damped_force = [&](DampingModel damping, const ContactConstants& constants) {
    model.damping = damping;
    const InteractionContext context = make_interaction(model, kNmc, kNmc);
    ContactHistory history;
    const LawOnBranch law = evaluate_contact_on_branch(constants, overlap, 0.0);
    return contact_force(context, constants, law.law.force, law.branch, approaching(speed), 1e-3, history).on_j.x() -
           law.law.force;
  };
  const ContactConstants spheres = constants_for(kNmc, {0.2, 0.2}, {0.2, 0.2});
  EXPECT_NEAR(damped_force(DampingModel::contact_radius, spheres), damped_force(DampingModel::hertz_tangent, spheres),
              1e-12 * damped_force(DampingModel::hertz_tangent, spheres));
  // The dashpot itself: c = 2 ζ sqrt(m* k) with k = dF_H/dδ, checked against a finite difference.
  const double h = 1e-7;
  const double tangent = (hertz_contact(hertz_shape_of(spheres), spheres.effective_modulus, overlap + h).force -
                          hertz_contact(hertz_shape_of(spheres), spheres.effective_modulus, overlap - h).force) /
                         (2.0 * h);
  EXPECT_NEAR(damped_force(DampingModel::hertz_tangent, spheres), 2.0 * 0.3 * std::sqrt(2.0 * tangent) * speed,
              1e-6 * damped_force(DampingModel::hertz_tangent, spheres));

  const ContactConstants elliptical = constants_for(kNmc, {0.3, 0.05}, {0.2, 0.1});
  ASSERT_LT(elliptical.f1, 0.999);
  const double radius = damped_force(DampingModel::contact_radius, elliptical);
  const double hertz = damped_force(DampingModel::hertz_tangent, elliptical);
  // k ratio = (f1/sqrt(f2)) / f2^{-3/2} = f1 f2; the dashpot goes with its square root.
  EXPECT_NEAR(radius / hertz, std::sqrt(elliptical.f1 * elliptical.f2), 1e-12);
}

// Sticking contact, one step of tangential motion v dt: F_t = −k_t ξ − c_t v_t with ξ = v dt.
TEST(ContactModel, TangentialStiffnessIsMindlinOrTheRatioOfTheNormalOne) {
  const ContactConstants constants = constants_for(kNmc, {0.2, 0.2}, {0.2, 0.2});
  const double overlap = 0.05;
  const double dt = 1e-4;
  const double slide = 0.1;  // small enough to stick: k_t v dt ≪ μ F_n
  ContactModel model;
  model.friction = 0.5;
  const auto tangential_force = [&](const ContactModel& m) {
    const InteractionContext context = make_interaction(m, kNmc, kNmc);
    ContactHistory history;
    const ContactKinematics kinematics{Eigen::Vector3d::UnitX(), slide * Eigen::Vector3d::UnitY(), 2.0};
    const LawOnBranch law = evaluate_contact_on_branch(constants, overlap, 0.0);
    const Eigen::Vector3d force =
        contact_force(context, constants, law.law.force, law.branch, kinematics, dt, history).on_j;
    EXPECT_NEAR(history.spring().y(), slide * dt, 1e-18);  // stuck: the spring took the whole motion
    return -force.y() / (slide * dt);                      // k_t
  };
  const double c_c = std::sqrt(constants.contact_radius_sq_per_overlap * overlap);
  const double shear = kNmc.youngs_modulus / (2.0 * (1.0 + kNmc.poisson_ratio));
  const double mindlin_stiffness = 8.0 * shear / (2.0 * (2.0 - kNmc.poisson_ratio)) * c_c;
  EXPECT_NEAR(tangential_force(model), mindlin_stiffness, 1e-12 * mindlin_stiffness);
  model.tangential = TangentialModel::ratio;
  model.tangential_stiffness_ratio = 0.8;
  const double normal_stiffness = 2.0 * constants.effective_modulus * c_c;
  EXPECT_NEAR(tangential_force(model), 0.8 * normal_stiffness, 1e-12 * normal_stiffness);
}

// A yielded contact under load turns between loading (δ = δ_*) and unloading at every small
// vibration. Its branch, and so k_n and k_t, must be continuous there: the contact radius of the
// loading branch is the top of the unloading curve, c² = R_e,pmax (δ_* − δ_p) f1²/f2 = β² R_e δ_*
// f1²/f2. With Hertz's radius while loading, k_t jumped by β at each turn, and the incremental
// spring (which keeps its force when k_t grows and ξ when it falls) lost the share 1 − 1/β of its
// force at every reloading: under load the packing's friction then crept with simulated time.
TEST(ContactModel, AYieldedContactTurningAtItsLargestOverlapKeepsItsTangentialForce) {
  const ContactConstants constants = constants_for(kNmc, {0.2, 0.2}, {0.2, 0.2});
  const double top = 20.0 * constants.yield_overlap;
  const LawOnBranch loading = evaluate_contact_on_branch(constants, top, 0.9 * top);
  const LawOnBranch unloading = evaluate_contact_on_branch(constants, top * (1.0 - 1e-9), top);
  ASSERT_NE(loading.law.regime, Regime::elastic);
  ASSERT_EQ(unloading.law.regime, Regime::unloading);
  // β² R_e δ_* against Hertz's R_e δ_*: the jump Hertz's radius would make (here β² = 2.9)
  ASSERT_GT(unloading.branch.radius_scale * unloading.branch.elastic_overlap, 1.2 * top);
  const auto radius_sq = [](const ElasticBranch& b) { return b.radius_scale * b.elastic_overlap; };
  EXPECT_NEAR(radius_sq(loading.branch), radius_sq(unloading.branch), 1e-7 * radius_sq(loading.branch));
  EXPECT_NEAR(loading.branch.coefficient, unloading.branch.coefficient, 1e-12 * loading.branch.coefficient);

  ContactModel model;
  model.friction = 0.5;
  model.normal_damping = model.tangential_damping = 0.0;
  const InteractionContext context = make_interaction(model, kNmc, kNmc);
  ContactHistory history;
  const auto step = [&](double overlap, double slide) {
    const ContactKinematics kinematics{Eigen::Vector3d::UnitX(), slide * Eigen::Vector3d::UnitY(), 2.0};
    const LawOnBranch law = evaluate_contact_on_branch(constants, overlap, history.max_overlap);
    history.max_overlap = law.law.max_overlap;
    return contact_force(context, constants, law.law.force, law.branch, kinematics, 1e-4, history).on_j.y();
  };
  for (int k = 1; k <= 100; ++k) (void)step(0.01 * k * top, 0.0);  // load to δ_* = top
  const double start = step(top, 0.01);                            // ξ = 1e-6: stuck
  ASSERT_LT(std::abs(start), 0.1 * model.friction * loading.law.force);
  double force = start;
  for (int turn = 0; turn < 100; ++turn) {  // unload by 1e-6 of δ_* and reload, at rest
    (void)step(top * (1.0 - 1e-6), 0.0);
    force = step(top, 0.0);
  }
  EXPECT_NEAR(force, start, 1e-3 * std::abs(start));  // Hertz's radius while loading: ×(1/β)^100
}

TEST(ContactModel, HertzNormalModelNeverYields) {
  ContactModel model;
  model.normal = NormalModel::hertz;
  const InteractionContext hertz = make_interaction(model, kNmc, kNmc);
  const InteractionContext plastic = make_interaction(ContactModel{}, kNmc, kNmc);
  EXPECT_EQ(plastic.material.yield_stress, kNmc.yield_stress);
  const ContactConstants constants =
      make_contact_constants(hertz.material, {0.2, 0.2}, {0.2, 0.2}, 0.0, 10.0, HertzMode::hale);
  EXPECT_EQ(evaluate_contact(constants, 2.0, 0.0).regime, Regime::elastic);  // 40 % of R_e, still Hertz
}

TEST(ContactModel, MindlinShearModulusOfUnlikeMaterialsReducesToTheLikeOne) {
  const Material steel{210000.0, 0.3, 900.0};
  const double like = make_interaction(ContactModel{}, steel, steel).shear_modulus;
  const Material almost{210000.0 * (1.0 + 1e-15), 0.3, 900.0};  // takes the general formula
  EXPECT_NEAR(make_interaction(ContactModel{}, steel, almost).shear_modulus, like, 1e-12 * like);
  const double g_steel = 210000.0 / 2.6;
  const double g_nmc = 142000.0 / 2.5;
  EXPECT_NEAR(make_interaction(ContactModel{}, steel, kNmc).shear_modulus,
              1.0 / ((2.0 - 0.3) / g_steel + (2.0 - 0.25) / g_nmc), 1e-9);
  EXPECT_EQ(make_interaction(ContactModel{}, steel, kNmc).material.yield_stress, 900.0);  // the softer yields
}

TEST(ContactParameters, OneVocabularyWithRangesAndImpliedRatioModel) {
  ContactModelBuilder builder{ContactModel{}};
  EXPECT_EQ(builder.set("damping_ratio", 0.2), "");
  EXPECT_EQ(builder.set("tangential_damping", 0.1), "");  // overrides the tangential one only
  EXPECT_EQ(builder.set("tangential_stiffness", 0.7), "");
  EXPECT_EQ(builder.set("damping_model", "hertz_tangent"), "");
  ContactModel model = builder.finish();
  EXPECT_EQ(model.normal_damping, 0.2);
  EXPECT_EQ(model.tangential_damping, 0.1);
  EXPECT_EQ(model.tangential, TangentialModel::ratio);  // a stiffness ratio selects the ratio model
  EXPECT_EQ(model.damping, DampingModel::hertz_tangent);
  EXPECT_EQ(builder.set("tangential_model", "mindlin"), "");
  EXPECT_EQ(builder.finish().tangential, TangentialModel::mindlin);  // given explicitly, it wins

  EXPECT_NE(builder.set("damping_ratio", 1.0).find("[0, 1)"), std::string::npos);
  EXPECT_NE(builder.set("friction", -0.1).find("[0, 10]"), std::string::npos);
  EXPECT_NE(builder.set("friction", NAN).find("[0, 10]"), std::string::npos);
  // Bounds from the physics: Mindlin's k_t/k_n < 4/3 for every admissible ν (1e300 once gave a
  // NaN kinetic energy in LAMMPS), and friction coefficients of real materials.
  EXPECT_NE(builder.set("tangential_stiffness", 1e300).find("[0, 1.5]"), std::string::npos);
  EXPECT_NE(builder.set("tangential_stiffness", 1.6).find("[0, 1.5]"), std::string::npos);
  EXPECT_EQ(builder.set("tangential_stiffness", 1.5), "");
  EXPECT_NE(builder.set("friction", 11.0).find("[0, 10]"), std::string::npos);
  EXPECT_EQ(builder.set("friction", 10.0), "");
  EXPECT_NE(builder.set("narrow_phase_final_step", 0.5).find("(0, 0.1]"), std::string::npos);
  EXPECT_EQ(builder.set("normal", "thornton"), "becker_kamlah or hertz");
  EXPECT_NE(builder.set("colour", 1.0), "");
  for (const auto& parameter : kContactParameters) EXPECT_EQ(find_contact_parameter(parameter.name), &parameter);
  EXPECT_EQ(validation_error(ContactModel{}, "[contact]"), "");
  ContactModel bad;
  bad.friction = -1.0;
  EXPECT_NE(validation_error(bad, "[contact]").find("[contact].friction"), std::string::npos);
  ContactModel stiff;
  stiff.tangential_stiffness_ratio = 1e300;
  EXPECT_EQ(validation_error(stiff, "pair_coeff"),
            "pair_coeff.tangential_stiffness = 1e+300: expected a finite number in [0, 1.5]");  // short form
}

TEST(ContactHistory, IsNineDoublesInTheDocumentedOrder) {
  ContactHistory history;
  history.max_overlap = 1.5;
  history.spring() = Eigen::Vector3d(2.0, 3.0, 4.0);
  history.set_warm_start(NarrowPhaseWarmStart{{5.0, 6.0, 7.0}, true});
  double flat[ContactHistory::kDoubles] = {};
  history.write_to(flat);
  history.spring_stiffness = 8.0;
  history.write_to(flat);
  const double expected[ContactHistory::kDoubles] = {1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 1.0, 8.0};
  for (std::size_t k = 0; k < ContactHistory::kDoubles; ++k) EXPECT_EQ(flat[k], expected[k]) << "double " << k;
  const ContactHistory back = ContactHistory::read_from(flat);
  EXPECT_EQ(back.warm_start().normal, history.warm_start().normal);
  EXPECT_TRUE(back.active());
  ContactHistory ended = back;
  ended.end_contact();
  EXPECT_FALSE(ended.active());
  EXPECT_EQ(ended.spring().norm(), 0.0);
  EXPECT_TRUE(ended.warm_start().valid);  // geometry outlives the contact
}

// Forces of one contact on two bodies: equal and opposite, and no net moment about any point.
TEST(PairContact, ForcesBalanceAndTorquesConserveAngularMomentum) {
  ContactModel model;
  model.friction = 0.3;
  model.normal_damping = model.tangential_damping = 0.1;
  const InteractionContext context = make_interaction(model, kNmc, kNmc);
  const Eigen::Vector3d axes_i(6.0, 5.0, 4.2), axes_j(3.0, 5.5, 4.0);
  const Eigen::Quaterniond q_i(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()));
  const Eigen::Quaterniond q_j(Eigen::AngleAxisd(-1.1, Eigen::Vector3d(-2, 1, 0.5).normalized()));
  const Eigen::Vector3d c_i(0.3, -0.2, 0.1), c_j(8.0, 2.0, -1.5);
  const BodyRef body_i{axes_i, c_i, q_i, std::cbrt(axes_i.prod())};
  const BodyRef body_j{axes_j, c_j, q_j, std::cbrt(axes_j.prod())};
  ContactHistory history;
  ContactCache cache;
  const PairSolution solution = solve_pair(body_i, body_j, false, history, cache, context);
  ASSERT_EQ(solution.status, PairStatus::contact);
  EXPECT_EQ(history.max_overlap, solution.law.max_overlap);
  EXPECT_EQ(cache.last_overlap, solution.overlap);
  const Eigen::Vector3d v_i(0.5, 0.1, 0.0), w_i(0.0, 0.0, 0.2), v_j(0.0, -0.3, 0.0), w_j(0.0, 3.0, -1.0);
  const PairForces forces =
      pair_forces(solution, c_i, BodyMotion{v_i, w_i, 3.0}, c_j, BodyMotion{v_j, w_j, 1.5}, context, 1e-3, history);
  EXPECT_GT(forces.contact.on_j.dot(solution.normal), 0.0);  // pushes J away from I
  const Eigen::Vector3d moment = forces.torque_on_i + forces.torque_on_j + (c_j - c_i).cross(forces.contact.on_j);
  EXPECT_LT(moment.norm(), 1e-12 * forces.contact.on_j.norm() * (c_j - c_i).norm());
}

// A sphere pressed on a flat, below yield: exact Hertz, F = 4/3 E_e sqrt(R) δ^{3/2} with R_e = R
// (the flat has no curvature) and E_e from eq. (3): the sphere's E/(1 − ν²) alone on a rigid
// flat, both compliances on an elastic one.
TEST(WallContactModel, SphereOnAFlatIsExactHertzWithTheWallsMaterial) {
  const double radius = 5.0;
  const Eigen::Vector3d axes = Eigen::Vector3d::Constant(radius);
  const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
  const Material steel{210000.0, 0.3, 1500.0};
  for (const bool as_ellipsoid : {false, true}) {
    for (const Material& wall : {rigid_material(), steel}) {
      const InteractionContext context = make_interaction(ContactModel{}, kNmc, wall);
      const double e_e = wall.youngs_modulus == rigid_material().youngs_modulus
                             ? kNmc.youngs_modulus / (1.0 - kNmc.poisson_ratio * kNmc.poisson_ratio)
                             : 1.0 / ((1.0 - 0.0625) / kNmc.youngs_modulus + (1.0 - 0.09) / steel.youngs_modulus);
      EXPECT_NEAR(context.material.effective_modulus, e_e, 1e-12 * e_e);
      const double overlap = 0.004;  // δ_Y ≈ 0.0085 µm on the steel plate, 0.086 µm on the rigid one
      const Ellipsoid shape(axes, Pose{Eigen::Vector3d(0.0, 0.0, radius - overlap), identity});
      const BodyRef body{axes, shape.center(), identity, radius, as_ellipsoid ? &shape : nullptr};
      ContactHistory history;
      ContactCache cache;
      const PairSolution solution = solve_wall(body, WallPlane{0.0, 1}, !as_ellipsoid, history, cache, context);
      ASSERT_EQ(solution.status, PairStatus::contact);
      EXPECT_EQ(solution.law.regime, Regime::elastic);
      const double hertz = 4.0 / 3.0 * e_e * std::sqrt(radius) * std::pow(overlap, 1.5);
      EXPECT_NEAR(solution.law.force, hertz, 1e-9 * hertz) << (as_ellipsoid ? "narrow phase" : "closed form");
      EXPECT_NEAR(solution.constants->equivalent_radius, radius, 1e-9 * radius);
    }
  }
  // The softer body yields first: a steel plate softer than NMC lowers the contact's Y.
  EXPECT_EQ(make_interaction(ContactModel{}, kNmc, steel).material.yield_stress, 1500.0);
  EXPECT_EQ(make_interaction(ContactModel{}, kNmc, rigid_material()).material.yield_stress, kNmc.yield_stress);
  // Mindlin against a rigid flat: G_e = G_I / (2 − ν_I).
  const double g = kNmc.youngs_modulus / (2.0 * (1.0 + kNmc.poisson_ratio));
  EXPECT_NEAR(make_interaction(ContactModel{}, kNmc, rigid_material()).shear_modulus, g / 1.75, 1e-9 * g);
}

}  // namespace
}  // namespace ellc

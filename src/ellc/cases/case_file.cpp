#include "ellc/cases/case_file.hpp"

#include <cmath>
#include <numbers>
#include <utility>

#include "ellc/geometry/tip_contact.hpp"
#include "ellc/io/input_error.hpp"

namespace ellc {

Material read_material(TableReader& table) {
  Material material;
  material.youngs_modulus = table.number("youngs_modulus");
  material.poisson_ratio = table.number("poisson_ratio");
  material.yield_stress = table.number("yield_stress");
  table.finish();
  if (const std::string error = validation_error(material, table.path()); !error.empty())
    throw InputError(table.source(), error);
  return material;
}

BodySpec read_body(TableReader& table, const std::optional<Material>& default_material,
                   std::vector<std::string>& warnings) {
  BodySpec body;
  const auto semi_axes = table.optional_numbers("semi_axes", 3);
  const auto aspect = table.optional_numbers("aspect", 3);
  const auto mean = table.optional_number("mean_radius");
  if (semi_axes && (aspect || mean))
    throw InputError(table.source(),
                     "[" + table.path() + "] gives both semi_axes and aspect/mean_radius: expected one of the two");
  const std::string length_range =
      "a length in [" + format_number(kMinLength) + ", " + format_number(kMaxLength) + "] (µm)";
  auto in_range = [](double length) { return length >= kMinLength && length <= kMaxLength; };
  if (semi_axes) {
    for (int axis = 0; axis < 3; ++axis) {
      if ((*semi_axes)[axis] <= 0.0)
        table.fail("semi_axes[" + std::to_string(axis) + "]", (*semi_axes)[axis], "a finite number > 0 (µm)");
      if (!in_range((*semi_axes)[axis]))
        table.fail("semi_axes[" + std::to_string(axis) + "]", (*semi_axes)[axis], length_range);
      body.semi_axes[axis] = (*semi_axes)[axis];
    }
  } else if (aspect) {
    if (!mean) table.fail("mean_radius", "missing", "a number > 0 (µm), required with aspect");
    if (*mean <= 0.0) table.fail("mean_radius", *mean, "a finite number > 0 (µm)");
    if (!in_range(*mean)) table.fail("mean_radius", *mean, length_range);
    for (int axis = 0; axis < 3; ++axis)
      if ((*aspect)[axis] <= 0.0 || !in_range((*aspect)[axis]))
        table.fail("aspect[" + std::to_string(axis) + "]", (*aspect)[axis],
                   "a finite number in [" + format_number(kMinLength) + ", " + format_number(kMaxLength) + "]");
    // Scale the aspect so that (abc)^{1/3} = r̂ (eq. 50); aspect[0] need not be exactly 1.
    // (Each ratio scaled by its cube root first: the product of three ratios may leave the range.)
    const Eigen::Vector3d ratios((*aspect)[0], (*aspect)[1], (*aspect)[2]);
    const double scale = *mean / (std::cbrt(ratios[0]) * std::cbrt(ratios[1]) * std::cbrt(ratios[2]));
    body.semi_axes = ratios * scale;
    for (int axis = 0; axis < 3; ++axis)
      if (!(in_range(body.semi_axes[axis])))
        table.fail("aspect", format_vector(ratios) + " with mean_radius = " + format_number(*mean),
                   "semi-axes in [" + format_number(kMinLength) + ", " + format_number(kMaxLength) +
                       "] (µm); this gives " + format_number(body.semi_axes[axis]));
  } else {
    table.fail("semi_axes", "missing", "semi_axes = [a, b, c] or aspect = [1, b/a, c/a] with mean_radius");
  }
  body.twist = table.number_or("twist_deg", 0.0) * std::numbers::pi / 180.0;

  if (auto own = table.optional_table("material")) {
    body.material = read_material(*own);
  } else if (default_material) {
    body.material = *default_material;
  } else {
    throw InputError(table.source(), "missing table [material] (or [" + table.field("material") + "])");
  }
  table.finish();

  const double b_over_a = body.semi_axes.y() / body.semi_axes.x();
  const double c_over_a = body.semi_axes.z() / body.semi_axes.x();
  auto outside = [](double ratio) {
    return ratio < kCalibratedAspectMin * (1 - 1e-12) || ratio > kCalibratedAspectMax * (1 + 1e-12);
  };
  if (outside(b_over_a) || outside(c_over_a))
    warnings.push_back(table.path() + " has aspect 1:" + format_number(b_over_a) + ":" + format_number(c_over_a) +
                       ", outside the calibrated range 1:[0.5..2]:[0.5..2] of the transition fits (eq. 52-53); "
                       "the law still evaluates");
  return body;
}

ModelSpec read_model(TableReader& table) {
  ModelSpec model;
  model.hertz = table.choice("hertz", {"hale", "exact"}, "hale") == "exact" ? HertzMode::exact : HertzMode::hale;
  auto& fit = model.law.fit;
  fit.lambda_amplitude = table.number_or("m", fit.lambda_amplitude);
  fit.lambda_rate = table.number_or("o", fit.lambda_rate);
  fit.lambda_offset = table.number_or("p", fit.lambda_offset);
  fit.epsilon_amplitude = table.number_or("s", fit.epsilon_amplitude);
  fit.epsilon_rate = table.number_or("t", fit.epsilon_rate);
  fit.epsilon_offset = table.number_or("u", fit.epsilon_offset);
  fit.transition_exponent = table.number_or("n", fit.transition_exponent);
  model.law.yield_pressure_factor = table.number_or("yield_pressure_factor", model.law.yield_pressure_factor);
  // form = "stiffness_ratio": λ_max, ε_max also depend on E_e/Y (transition_fit.hpp); its exponents
  // are required (a fit form without its E/Y coefficients would silently be the paper's).
  const char* const stiffness_keys[] = {"lambda_stiffness_exponent", "epsilon_stiffness_exponent",
                                        "reference_stiffness_ratio"};
  if (table.choice("form", {"paper", "stiffness_ratio"}, "paper") == "stiffness_ratio") {
    fit.form = TransitionForm::stiffness_ratio;
    const std::string expected =
        "a number (form = \"stiffness_ratio\" needs the E_e/Y exponents; `ellc fit "
        "--form stiffness_ratio` writes them)";
    for (const char* key : {stiffness_keys[0], stiffness_keys[1]})
      if (!table.optional_number(key)) table.fail(key, "missing", expected);
    fit.lambda_stiffness_exponent = table.number("lambda_stiffness_exponent");
    fit.epsilon_stiffness_exponent = table.number("epsilon_stiffness_exponent");
    fit.reference_stiffness_ratio = table.number_or("reference_stiffness_ratio", fit.reference_stiffness_ratio);
  } else {
    for (const char* key : stiffness_keys)
      if (table.has(key))
        table.fail(key, "given", "form = \"stiffness_ratio\" in [model] to use it (form is \"paper\")");
  }
  table.finish();
  if (const std::string error = validation_error(model.law); !error.empty()) throw InputError(table.source(), error);
  return model;
}

std::vector<ModelDifference> model_differences(const ModelSpec& first, const ModelSpec& second) {
  std::vector<ModelDifference> differences;
  const auto name = [](HertzMode mode) { return std::string(mode == HertzMode::exact ? "\"exact\"" : "\"hale\""); };
  const auto form = [](TransitionForm f) {
    return std::string(f == TransitionForm::stiffness_ratio ? "\"stiffness_ratio\"" : "\"paper\"");
  };
  if (first.hertz != second.hertz) differences.push_back({"hertz", name(first.hertz), name(second.hertz)});
  const TransitionFit& a = first.law.fit;
  const TransitionFit& b = second.law.fit;
  const std::pair<const char*, std::pair<double, double>> numbers[] = {
      {"m", {a.lambda_amplitude, b.lambda_amplitude}},
      {"o", {a.lambda_rate, b.lambda_rate}},
      {"p", {a.lambda_offset, b.lambda_offset}},
      {"s", {a.epsilon_amplitude, b.epsilon_amplitude}},
      {"t", {a.epsilon_rate, b.epsilon_rate}},
      {"u", {a.epsilon_offset, b.epsilon_offset}},
      {"n", {a.transition_exponent, b.transition_exponent}},
      {"yield_pressure_factor", {first.law.yield_pressure_factor, second.law.yield_pressure_factor}},
      {"lambda_stiffness_exponent", {a.lambda_stiffness_exponent, b.lambda_stiffness_exponent}},
      {"epsilon_stiffness_exponent", {a.epsilon_stiffness_exponent, b.epsilon_stiffness_exponent}},
      {"reference_stiffness_ratio", {a.reference_stiffness_ratio, b.reference_stiffness_ratio}}};
  if (a.form != b.form) differences.push_back({"form", form(a.form), form(b.form)});
  for (const auto& [key, values] : numbers)
    if (values.first != values.second)
      differences.push_back({key, format_number(values.first), format_number(values.second)});
  return differences;
}

BodyPair read_body_pair(TableReader& root, std::vector<std::string>& warnings) {
  std::optional<Material> shared_material;
  if (auto material = root.optional_table("material")) shared_material = read_material(*material);
  BodyPair pair;
  auto table_i = root.table("body_I");
  pair.body_i = read_body(table_i, shared_material, warnings);
  auto table_j = root.table("body_J");
  pair.body_j = read_body(table_j, shared_material, warnings);
  return pair;
}

ContactConstants case_contact_constants(const BodySpec& body_i, const BodySpec& body_j, HertzMode mode,
                                        const LawParameters& law) {
  const TipContact tip = tip_contact({body_i.semi_axes, body_i.twist}, {body_j.semi_axes, body_j.twist});
  return make_contact_constants(mix(body_i.material, body_j.material), tip.body_i, tip.body_j, tip.alpha,
                                mean_radius(body_i.semi_axes) + mean_radius(body_j.semi_axes), mode, law);
}

namespace {

std::string material_text(const Material& material, const std::string& table) {
  return table + " youngs_modulus = " + format_number(material.youngs_modulus) +
         ", poisson_ratio = " + format_number(material.poisson_ratio) +
         ", yield_stress = " + format_number(material.yield_stress);
}

bool same_material(const Material& a, const Material& b) {
  return a.youngs_modulus == b.youngs_modulus && a.poisson_ratio == b.poisson_ratio && a.yield_stress == b.yield_stress;
}

}  // namespace

std::string format_vector(const Eigen::Vector3d& v) {
  std::string text(1, '[');  // (appended piece by piece: GCC 12 warns falsely on "[" + std::string)
  text += format_number(v.x());
  text += ", ";
  text += format_number(v.y());
  text += ", ";
  text += format_number(v.z());
  text += ']';
  return text;
}

TwoBodyFields two_body_fields(const std::string& source, const BodySpec& body_i, const std::string& name_i,
                              const BodySpec& body_j, const std::string& name_j) {
  TwoBodyFields fields;
  fields.source = source;
  fields.shape = name_i + ".semi_axes = " + format_vector(body_i.semi_axes) + ", " + name_j +
                 ".semi_axes = " + format_vector(body_j.semi_axes);
  fields.material = same_material(body_i.material, body_j.material)
                        ? material_text(body_i.material, "[material]")
                        : material_text(body_i.material, "[" + name_i + ".material]") + "; " +
                              material_text(body_j.material, "[" + name_j + ".material]");
  return fields;
}

std::string traced_constants_error(const ContactConstants& c, const TwoBodyFields& fields) {
  std::string error = validation_error(c);
  if (error.empty()) return {};
  auto bad = [](double value) { return !std::isfinite(value) || value <= 0.0; };
  std::string origin;
  if (bad(c.effective_modulus) || bad(c.yield_stress)) {
    origin = fields.material;
  } else if (bad(c.equivalent_radius) || bad(c.f1) || bad(c.f2) || !std::isfinite(c.eccentricity_sq)) {
    origin = fields.shape + " (the curvatures at the contact)";
  } else if (bad(c.yield_overlap)) {
    origin = fields.material + " with " + fields.shape + " (delta_Y ~ (Y/E)^2 R_e)";
  } else {
    return error;  // λ_max, ε_max: the message already names the [model] fit
  }
  return "the inputs " + origin + " give no valid contact law: " + error;
}

namespace {

CurveCase read_case(const toml::table& root_table, const std::string& source) {
  TableReader root(root_table, "", source);
  CurveCase result;
  auto [body_i, body_j] = read_body_pair(root, result.warnings);
  result.body_i = std::move(body_i);
  result.body_j = std::move(body_j);
  {
    auto protocol = root.table("protocol");
    const auto absolute = protocol.optional_numbers("waypoints");
    const auto relative = protocol.optional_numbers("waypoints_relative");
    if (absolute && relative)
      throw InputError(source, "[protocol] gives both waypoints and waypoints_relative: expected one of the two");
    if (!absolute && !relative)
      protocol.fail("waypoints", "missing",
                    "waypoints = [...] (µm) or waypoints_relative = [...] (fractions of r̂^I + r̂^J)");
    const double scale = relative ? mean_radius(result.body_i.semi_axes) + mean_radius(result.body_j.semi_axes) : 1.0;
    const auto& given = absolute ? *absolute : *relative;
    const char* key = absolute ? "waypoints" : "waypoints_relative";
    // The bodies touch tip to tip along x: at δ = a_I + a_J their centres coincide, beyond it the
    // configuration has no meaning (and 1e308 would overflow δ^{3/2}).
    const double reach = result.body_i.semi_axes.x() + result.body_j.semi_axes.x();
    for (std::size_t index = 0; index < given.size(); ++index) {
      if (given[index] < 0.0)
        protocol.fail(std::string(key) + "[" + std::to_string(index) + "]", given[index], "a finite number >= 0");
      const double overlap = given[index] * scale;
      if (overlap > reach)
        protocol.fail(std::string(key) + "[" + std::to_string(index) + "]", given[index],
                      "an overlap of at most a_I + a_J = " + format_number(reach) +
                          " µm (the x semi-axes of body_I and body_J; the centres coincide there)");
      result.waypoints.push_back(overlap);
    }
    if (given.size() < 2) protocol.fail(key, "an array of 1 element", "at least two waypoints");
    result.points_per_segment = protocol.integer_at_least("points_per_segment", 1, 50);
    if (result.points_per_segment > kMaxPointsPerSegment)
      protocol.fail("points_per_segment", static_cast<double>(result.points_per_segment),
                    "at most " + std::to_string(kMaxPointsPerSegment));
    if ((given.size() - 1) * static_cast<std::size_t>(result.points_per_segment) > kMaxCurvePoints)
      protocol.fail("points_per_segment", static_cast<double>(result.points_per_segment),
                    "at most " + std::to_string(kMaxCurvePoints) + " points in all (" +
                        std::to_string(given.size() - 1) + " segments)");
    protocol.finish();
  }
  if (auto model = root.optional_table("model")) result.model = read_model(*model);
  root.finish();
  // The law must be evaluable for these bodies and materials; a bad derived quantity (R_e, δ_Y)
  // is reported with the input fields it comes from.
  const ContactConstants constants =
      case_contact_constants(result.body_i, result.body_j, result.model.hertz, result.model.law);
  if (const std::string error =
          traced_constants_error(constants, two_body_fields(source, result.body_i, "body_I", result.body_j, "body_J"));
      !error.empty())
    throw InputError(source, error);
  return result;
}

}  // namespace

CurveCase read_curve_case(const std::string& path) { return read_case(parse_toml_file(path), path); }

CurveCase parse_curve_case(std::string_view toml_text, const std::string& source) {
  return read_case(parse_toml_text(toml_text, source), source);
}

}  // namespace ellc

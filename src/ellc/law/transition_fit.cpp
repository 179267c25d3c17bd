#include "ellc/law/transition_fit.hpp"

#include <cmath>
#include <sstream>

namespace ellc {

double TransitionFit::lambda_max(double radius_ratio) const noexcept {
  return lambda_amplitude * std::exp(lambda_rate * radius_ratio) + lambda_offset;
}

double TransitionFit::epsilon_max(double radius_ratio) const noexcept {
  return epsilon_amplitude * std::exp(epsilon_rate * radius_ratio) + epsilon_offset;
}

namespace {

// (η/η_ref)^q; exactly 1 for the paper's form or q = 0, whatever η (also a rigid Y = ∞).
double stiffness_factor(const TransitionFit& fit, double exponent, double stiffness_ratio) noexcept {
  if (fit.form == TransitionForm::paper || exponent == 0.0) return 1.0;
  return std::pow(stiffness_ratio / fit.reference_stiffness_ratio, exponent);
}

}  // namespace

double TransitionFit::lambda_max_for(double radius_ratio, double stiffness_ratio) const noexcept {
  return lambda_max(radius_ratio) * stiffness_factor(*this, lambda_stiffness_exponent, stiffness_ratio);
}

double TransitionFit::epsilon_max_for(double radius_ratio, double stiffness_ratio) const noexcept {
  return epsilon_max(radius_ratio) * stiffness_factor(*this, epsilon_stiffness_exponent, stiffness_ratio);
}

LawParameters LawParameters::elastic_fully_plastic() const noexcept {
  LawParameters thornton = *this;
  thornton.fit.lambda_amplitude = 0.0;
  thornton.fit.lambda_offset = yield_pressure_factor;
  thornton.fit.lambda_stiffness_exponent = 0.0;  // λ ≡ 1.6 for every material
  return thornton;
}

std::string validation_error(const LawParameters& parameters) {
  const auto& fit = parameters.fit;
  const struct {
    const char* name;
    double value;
  } all[] = {{"m", fit.lambda_amplitude},
             {"o", fit.lambda_rate},
             {"p", fit.lambda_offset},
             {"s", fit.epsilon_amplitude},
             {"t", fit.epsilon_rate},
             {"u", fit.epsilon_offset},
             {"n", fit.transition_exponent},
             {"yield_pressure_factor", parameters.yield_pressure_factor},
             {"lambda_stiffness_exponent", fit.lambda_stiffness_exponent},
             {"epsilon_stiffness_exponent", fit.epsilon_stiffness_exponent},
             {"reference_stiffness_ratio", fit.reference_stiffness_ratio}};
  for (const auto& [name, value] : all) {
    if (!std::isfinite(value)) {
      std::ostringstream out;
      out << "model." << name << " = " << value << ": expected a finite number";
      return out.str();
    }
  }
  std::ostringstream out;
  out.precision(17);
  if (fit.transition_exponent <= 0.0)
    out << "model.n = " << fit.transition_exponent << ": expected a number > 0";
  else if (parameters.yield_pressure_factor <= 0.0)
    out << "model.yield_pressure_factor = " << parameters.yield_pressure_factor << ": expected a number > 0";
  else if (fit.reference_stiffness_ratio <= 0.0)
    out << "model.reference_stiffness_ratio = " << fit.reference_stiffness_ratio
        << ": expected a number > 0 (E_e/Y of the reference material)";
  return out.str();
}

}  // namespace ellc

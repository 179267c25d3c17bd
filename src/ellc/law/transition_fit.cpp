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

LawParameters LawParameters::elastic_fully_plastic() const noexcept {
  LawParameters thornton = *this;
  thornton.fit.lambda_amplitude = 0.0;
  thornton.fit.lambda_offset = yield_pressure_factor;
  return thornton;
}

std::string validation_error(const LawParameters& parameters) {
  const auto& fit = parameters.fit;
  const struct {
    const char* name;
    double value;
  } all[] = {{"m", fit.lambda_amplitude},    {"o", fit.lambda_rate},
             {"p", fit.lambda_offset},       {"s", fit.epsilon_amplitude},
             {"t", fit.epsilon_rate},        {"u", fit.epsilon_offset},
             {"n", fit.transition_exponent}, {"yield_pressure_factor", parameters.yield_pressure_factor}};
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
  return out.str();
}

}  // namespace ellc

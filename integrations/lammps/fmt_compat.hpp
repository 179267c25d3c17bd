#pragma once
// Compatibility between Debian's LAMMPS 29Sep2021 headers and Debian's fmt 9.
//
// LAMMPS's public headers (pointers.h, utils.h, error.h) include "fmt/format.h" and, inside
// templates, call fmt::make_args_checked<Args...>(format, args...). fmt 9 removed that function.
// This header supplies an equivalent before any LAMMPS header is parsed, so the templates compile.
//
// Rule for the code of this integration: never *call* a LAMMPS function whose signature carries fmt
// types (Error::_all, utils::fmtargs_logmesg, the variadic error->all overloads). liblammps.so was
// built against its own bundled fmt, so such calls would not link or would pass the wrong layout.
// Use the std::string overloads (see ellc_lammps::fail) instead.

#include <fmt/format.h>

#include <type_traits>

#if FMT_VERSION >= 90000
namespace fmt {
template <typename... Args, typename S>
[[nodiscard]] inline auto make_args_checked(const S& /*format*/, const std::remove_reference_t<Args>&... args) {
  return fmt::make_format_args(args...);
}
}  // namespace fmt
#endif

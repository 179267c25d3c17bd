#!/usr/bin/env bash
# The downstream checks of tests/downstream/CMakeLists.txt, one step per ctest entry:
#
#   downstream.sh install | cli | find_package | pkg_config | headers | lmp_ellc
#
# Environment (set by CMake): ELLC_BUILD_DIR, ELLC_PREFIX (emptied and installed into by
# `install`), ELLC_WORK (scratch folder), ELLC_SOURCE_DIR, ELLC_LIBDIR and ELLC_PYTHONDIR (relative
# to the prefix), ELLC_VERSION, CMAKE_COMMAND, CMAKE_GENERATOR, CMAKE_MAKE_PROGRAM, CXX.
# Every step after `install` uses only the prefix: the installed programs, headers, library,
# CMake and pkg-config files, never the source or build tree.
set -euo pipefail
step=$1
prefix=$ELLC_PREFIX
work=$ELLC_WORK
csv=$work/case2.csv                       # written by `cli`, read by the consumers
case_file=$prefix/share/ellc/examples/paper_case2.toml
mkdir -p "$work"

case $step in
install)
  rm -rf "$prefix"
  "$CMAKE_COMMAND" --install "$ELLC_BUILD_DIR" --prefix "$prefix"
  (cd "$prefix" && find . -type f | sort)
  ;;

cli)
  # The installed CLI, run without PYTHONPATH: its plots must use the package installed next to it.
  unset PYTHONPATH ELLC_PYTHON_DIR
  version=$("$prefix/bin/ellc" --version)
  echo "$version"
  grep -qx "ellc $ELLC_VERSION" <<<"$version"
  grep -qF "package in $prefix/$ELLC_PYTHONDIR" <<<"$version" ||
    { echo "the installed ellc does not take its plots from $prefix/$ELLC_PYTHONDIR"; exit 1; }
  "$prefix/bin/ellc" --help >/dev/null
  rm -f "$csv" "$work/case2.png"
  (cd "$work" && "$prefix/bin/ellc" curve "$case_file" -o "$csv" --plot "$work/case2.png")
  test -s "$csv" && test -s "$work/case2.png"
  ;;

find_package)
  # tests/downstream/consumer: find_package(ellc CONFIG REQUIRED), from this prefix only.
  build=$work/consumer-build
  rm -rf "$build"
  "$CMAKE_COMMAND" -S "$ELLC_SOURCE_DIR/tests/downstream/consumer" -B "$build" -G "$CMAKE_GENERATOR" \
    -DCMAKE_MAKE_PROGRAM="$CMAKE_MAKE_PROGRAM" -DCMAKE_CXX_COMPILER="$CXX" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$prefix" -DELLC_EXPECTED_PREFIX="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  "$CMAKE_COMMAND" --build "$build"
  "$build/paper_case2" "$csv" "$case_file"
  ;;

pkg_config)
  # The same program, compiled as the README says: g++ ... $(pkg-config --cflags --libs ellc).
  export PKG_CONFIG_PATH=$prefix/$ELLC_LIBDIR/pkgconfig
  test "$(pkg-config --modversion ellc)" = "$ELLC_VERSION"
  echo "pkg-config --cflags --libs ellc: $(pkg-config --cflags --libs ellc)"
  # shellcheck disable=SC2046  # the flags are meant to split
  "$CXX" -std=c++20 -O2 "$ELLC_SOURCE_DIR/tests/downstream/consumer/paper_case2.cpp" \
    $(pkg-config --cflags --libs ellc) -o "$work/paper_case2_pkg_config"
  "$work/paper_case2_pkg_config" "$csv" "$case_file"
  ;;

headers)
  # Include closure: every "…" include of an installed header is installed too, and all installed
  # headers compile together with nothing but the pkg-config flags (Eigen, toml++ and the prefix).
  include=$prefix/include
  headers=$(cd "$include" && find ellc -name '*.hpp' | sort)
  test -n "$headers"
  missing=0
  for header in $headers; do
    while read -r target; do
      [[ -f $include/$target || -f $include/$(dirname "$header")/$target ]] && continue
      echo "$header includes \"$target\", which is not installed"
      missing=1
    done < <(sed -nE 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"([^"]+)".*/\1/p' "$include/$header")
  done
  ((missing == 0))
  echo "$(wc -w <<<"$headers") installed headers:" $(cut -d/ -f2 <<<"$headers" | sort -u)
  {
    for header in $headers; do echo "#include <$header>"; done
    echo "int main() { return 0; }"
  } >"$work/all_headers.cpp"
  export PKG_CONFIG_PATH=$prefix/$ELLC_LIBDIR/pkgconfig
  # shellcheck disable=SC2046
  "$CXX" -std=c++20 -fsyntax-only -Wall -Wextra $(pkg-config --cflags ellc) "$work/all_headers.cpp"
  ;;

lmp_ellc)
  # The installed LAMMPS executable: -h, then the installed two-particle example (pair_style
  # ellipsoid/bk, paper case 2) on a coarse path; it must write its force-overlap table.
  "$prefix/bin/lmp_ellc" -h | sed -n '2,3p'
  rm -f "$work/lammps_case2.csv"
  (cd "$work" && "$prefix/bin/lmp_ellc" -in "$prefix/share/ellc/examples/lammps/in.two_particle_case2" \
     -var n 20 -var out lammps_case2.csv -log none -screen none)
  test "$(head -n 1 "$work/lammps_case2.csv")" = "overlap,force"
  test "$(wc -l <"$work/lammps_case2.csv")" -gt 20
  echo "lmp_ellc ran the two-particle example: $(($(wc -l <"$work/lammps_case2.csv") - 1)) rows"
  ;;

*)
  echo "downstream.sh: unknown step $step" >&2
  exit 2
  ;;
esac

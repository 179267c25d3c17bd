# Sourced by the build scripts (build.sh, sanitizers.sh, fuzz.sh): compile through ccache when it
# is installed (scripts/setup.sh installs it), so that a rebuild of unchanged sources, in this
# checkout or in a fresh clone elsewhere on the same machine (CI clones main into another folder),
# takes seconds instead of the cold build's minutes. Set ELLC_CCACHE=0 to compile without it.
#
# CCACHE_BASEDIR makes the paths inside the checkout relative, so two clones share entries;
# CCACHE_NOHASHDIR lets the -g sanitizer builds share them too (their debug info then names the
# directory that first compiled the file, which only a debugger would notice). Only newly
# configured build directories pick the launcher up: CMake caches it.
if [[ ${ELLC_CCACHE:-1} != 0 ]] && command -v ccache >/dev/null; then
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(pwd -P)} CCACHE_NOHASHDIR=1
fi

#!/usr/bin/env bash
# Builds the Debian package ellc_<version>_amd64.deb and checks it on a clean Debian 12 system.
#
#   sudo scripts/check_deb.sh [--extract] [BUILD_DIR]        (BUILD_DIR defaults to build)
#
# 1. Builds BUILD_DIR (configured like scripts/build.sh if it is not yet), runs `cpack -G DEB` there
#    and prints the package's control fields and file list.
# 2. `apt-get install --simulate ./ellc_*.deb` on this machine: every Depends resolves in its apt
#    sources.
# 3. A clean root: a minimal Debian bookworm made by debootstrap from the Debian archive this machine's apt uses (kept in
#    BUILD_DIR/deb-check/base and copied fresh for each run). In it, first
#    `apt-get install --no-install-recommends ./ellc_*.deb` (the Depends alone), then these must work:
#      ellc --help; ellc --version (plots from /usr/lib/python3/dist-packages);
#      ellc curve /usr/share/ellc/examples/paper_case2.toml -o case2.csv --plot case2.png;
#      python3: import ellc (the compiled module), paper case 2 = the CSV, ellc.plots on arrays, ellc.dem steps;
#      lmp_ellc -h, and lmp_ellc on the installed examples/lammps/in.two_particle_case2.
#    Then the Recommends (Eigen and toml++ headers, pkg-config) and g++, and the same checks
#    plus tests/downstream/consumer/paper_case2.cpp built with $(pkg-config --cflags --libs ellc)
#    against /usr, which must reproduce the CSV. Last, `apt-get purge ellc` must leave no file of
#    the package behind.
# 4. `DESTDIR=<root> cmake --install BUILD_DIR --prefix /usr/local`, and the same checks against
#    /usr/local with no PYTHONPATH or PKG_CONFIG_PATH.
#    Needs root (debootstrap, chroot, mount) and access to Debian's archive; the first run
#    downloads about 250 MB and takes several minutes, later runs reuse the base system and the
#    downloaded .debs (BUILD_DIR/deb-check/apt-archives). The root is deleted after a successful
#    run and kept after a failed one.
#
# --extract (or no debootstrap, or not root): instead of 3 and 4, unpacks the package with `dpkg-deb -x`
# into BUILD_DIR/deb-check/extract and runs the same checks, the consumer included, from there
# against this machine's libraries (PATH, PYTHONPATH and PKG_CONFIG_PATH point into the unpacked
# /usr). That shows the files work, not that the Depends are complete.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=chroot
if [[ ${1:-} == --extract ]]; then mode=extract; shift; fi
build=${1:-build}
jobs=${JOBS:-$(nproc)}
suite=bookworm
# The Debian archives this machine's apt uses (deb822 .sources or the classic sources.list).
apt_uri() {
  local pattern=$1
  # Either file may be missing (Debian 12 images often have only the .sources): with pipefail a
  # grep that finds no file must not end the script.
  { grep -hE '^URIs:' /etc/apt/sources.list.d/*.sources 2>/dev/null | awk '{print $2}' || true
    grep -hE '^deb ' /etc/apt/sources.list 2>/dev/null | awk '{print $2}' || true; } | { grep -E "$pattern" || true; } | head -1
}
mirror=${DEB_MIRROR:-$(apt_uri 'debian/?$')}
security_mirror=${DEB_SECURITY_MIRROR:-$(apt_uri 'debian-security/?$')}
[[ -n $mirror ]] || { echo "check_deb: no Debian archive in /etc/apt (set DEB_MIRROR)" >&2; exit 2; }

# --- 1. the package ---------------------------------------------------------------------------
if [[ ! -f $build/CMakeCache.txt ]]; then
  generator=()
  command -v ninja >/dev/null && generator=(-G Ninja)
  cmake -S . -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" -j "$jobs"
rm -f "$build"/ellc_*.deb
(cd "$build" && cpack -G DEB)
deb=$(ls "$build"/ellc_*_amd64.deb)
deb=$(realpath "$deb")
echo "== $deb"
dpkg-deb --field "$deb" Package Version Architecture Depends Recommends
dpkg-deb --contents "$deb" | awk '{print $NF}' | grep -v '/$'

# --- 2. Depends resolve here -------------------------------------------------------------------
echo "== apt-get install --simulate $(basename "$deb")"
apt-get install --simulate "$deb" | grep -E '^(Inst|Conf|E:)|is already the newest' || true
apt-get install --simulate "$deb" >/dev/null

# The checks of step 3, run inside the root (chroot) or against the unpacked package (extract).
read -r -d '' checks <<'EOF' || true
set -euo pipefail
cd "$(mktemp -d)"
echo "-- ellc --help";    ellc --help | head -n 3
echo "-- ellc --version"; ellc --version
ellc --version | grep -q "package in $ELLC_EXPECT_PYTHONDIR"
echo "-- ellc curve paper_case2 --plot"
ellc curve "$ELLC_EXAMPLES/paper_case2.toml" -o case2.csv --plot case2.png | tail -n 4
test -s case2.csv && test -s case2.png
echo "-- /usr/bin/python3: import ellc"
/usr/bin/python3 - <<'PY'
import csv, os
import numpy as np
import ellc
from ellc import plots
assert ellc.HAVE_CORE, "ellc._ellc did not import"
expected = os.environ["ELLC_EXPECT_PYTHONDIR"]
assert ellc.__file__.startswith(expected + "/"), f"ellc imported from {ellc.__file__}, expected {expected}"
case = ellc.read_curve_case(os.path.join(os.environ["ELLC_EXAMPLES"], "paper_case2.toml"))
contact = ellc.Contact.from_case(case)
path = case.overlap_path()
force = contact.evaluate_path(path).force
with open("case2.csv", newline="") as handle:
    reference = np.array([float(row["force"]) for row in csv.DictReader(handle)])
assert np.allclose(force, reference, rtol=1e-12, atol=0.0), "force differs from ellc curve"
c = contact.constants
plots.curve_figure(path / c.yield_overlap, force / c.yield_force).savefig("from_arrays.png")
scenario = ellc.dem.Scenario.from_file(os.path.join(os.environ["ELLC_EXAMPLES"], "calendering_quick.toml"))
run = ellc.dem.Run(scenario.with_changes({"packing": {"count": 10}}), write_files=False)
run.run(50)
assert run.step == 50 and run.particles.position.shape == (10, 3) and np.isfinite(run.particles.position).all()
print(f"import ellc: {ellc.__file__}; paper case 2 = ellc curve over {len(path)} points; plot from arrays drawn; "
      f"ellc.dem stepped 10 particles")
PY
echo "-- lmp_ellc -h; lmp_ellc -in .../examples/lammps/in.two_particle_case2"
lmp_ellc -h | sed -n '2p'
lmp_ellc -in "$ELLC_EXAMPLES/lammps/in.two_particle_case2" -var n 20 -var out lammps.csv -log none -screen none
test "$(head -n 1 lammps.csv)" = "overlap,force" && test "$(wc -l <lammps.csv)" -gt 20
echo "lmp_ellc: pair_style ellipsoid/bk ran paper case 2 ($(($(wc -l <lammps.csv) - 1)) rows)"
if [[ ${ELLC_CHECK_DEV:-no} == yes ]]; then
  echo "-- g++ -std=c++20 paper_case2.cpp \$(pkg-config --cflags --libs ellc)"
  pkg-config --cflags --libs ellc
  # shellcheck disable=SC2046
  g++ -std=c++20 -O2 "$ELLC_CONSUMER" $(pkg-config --cflags --libs ellc) -o paper_case2
  ./paper_case2 case2.csv "$ELLC_EXAMPLES/paper_case2.toml"
fi
EOF

run_extract() {
  local dir=$build/deb-check/extract
  rm -rf "$dir"
  mkdir -p "$dir"
  dpkg-deb -x "$deb" "$dir"
  dir=$(realpath "$dir")
  echo "== checks on the unpacked package in $dir (this machine's libraries)"
  local pc
  pc=$(find "$dir/usr/lib" -name ellc.pc)
  env PATH="$dir/usr/bin:$PATH" PYTHONPATH="$dir/usr/lib/python3/dist-packages" \
      PKG_CONFIG_PATH="$(dirname "$pc")" ELLC_EXAMPLES="$dir/usr/share/ellc/examples" \
      ELLC_EXPECT_PYTHONDIR="$dir/usr/lib/python3/dist-packages" \
      ELLC_CHECK_DEV=yes ELLC_CONSUMER="$PWD/tests/downstream/consumer/paper_case2.cpp" \
      OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 bash -c "$checks"
  echo "== check_deb: package built, Depends resolve, unpacked package works (no clean root: --extract)"
}

if [[ $mode == chroot ]] && { [[ $(id -u) -ne 0 ]] || ! command -v debootstrap >/dev/null; }; then
  echo "check_deb: needs root and debootstrap (apt-get install debootstrap) for the clean root; using --extract"
  mode=extract
fi
if [[ $mode == extract ]]; then
  run_extract
  exit 0
fi

# --- 3. a clean Debian root --------------------------------------------------------------------
work=$(realpath -m "$build/deb-check")
base=$work/base
root=$work/root
cache=$work/apt-archives
mkdir -p "$work" "$cache"
if [[ ! -f $base/.complete ]]; then
  echo "== debootstrap --variant=minbase $suite $base $mirror"
  rm -rf "$base"
  debootstrap --variant=minbase "$suite" "$base" "$mirror"
  cat >"$base/etc/apt/sources.list" <<EOF
deb $mirror $suite main
deb $mirror $suite-updates main
${security_mirror:+deb $security_mirror $suite-security main}
EOF
  touch "$base/.complete"
fi

cleanup() {
  for mount_point in "$root/proc" "$root/sys" "$root/dev/pts" "$root/dev"; do
    mountpoint -q "$mount_point" && umount "$mount_point"
  done
  true
}
trap cleanup EXIT
cleanup
if [[ -d $root ]] && findmnt -rn -o TARGET | grep -q "^$root/"; then
  echo "check_deb: something is still mounted under $root; unmount it first" >&2
  exit 1
fi
rm -rf --one-file-system "$root"
cp -a "$base" "$root"
mount -t proc proc "$root/proc"
mount --bind /sys "$root/sys"   # hwloc (Open MPI) reads the CPU topology there
mount --bind /dev "$root/dev"
mount --bind /dev/pts "$root/dev/pts"
cp /etc/resolv.conf "$root/etc/resolv.conf"
cp "$cache"/*.deb "$root/var/cache/apt/archives/" 2>/dev/null || true
cp "$deb" "$root/tmp/"
in_root() { chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
              DEBIAN_FRONTEND=noninteractive "$@"; }

deb_name=$(basename "$deb")
echo "== clean root $root: apt-get install --no-install-recommends ./$deb_name (Depends only)"
in_root apt-get update -q
in_root apt-get install -y -q --no-install-recommends "/tmp/$deb_name"
cp "$root"/var/cache/apt/archives/*.deb "$cache/" 2>/dev/null || true
check_env=(ELLC_EXAMPLES=/usr/share/ellc/examples ELLC_EXPECT_PYTHONDIR=/usr/lib/python3/dist-packages
           OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1)
echo "== checks in the clean root, with the Depends alone"
in_root env "${check_env[@]}" bash -c "$checks"

# The development side: the Recommends (Eigen and toml++ headers, pkg-config) and a compiler; then
# the downstream consumer, built with pkg-config against /usr, must reproduce `ellc curve`.
recommends=$(dpkg-deb --field "$deb" Recommends | tr -d ',')
echo "== clean root: apt-get install --no-install-recommends $recommends g++"
# shellcheck disable=SC2086  # one word per package
in_root apt-get install -y -q --no-install-recommends $recommends g++ >/dev/null
cp "$root"/var/cache/apt/archives/*.deb "$cache/" 2>/dev/null || true
cp tests/downstream/consumer/paper_case2.cpp "$root/tmp/"
echo "== checks in the clean root, with the Recommends: the consumer through pkg-config"
in_root env "${check_env[@]}" ELLC_CHECK_DEV=yes ELLC_CONSUMER=/tmp/paper_case2.cpp bash -c "$checks"

echo "== apt-get purge ellc"
files=$(dpkg-deb --contents "$deb" | awk '{print $NF}' | sed 's|^\./|/|' | grep -v '/$')
in_root apt-get purge -y -q ellc >/dev/null
left=0
for file in $files; do
  if [[ -e $root$file ]]; then echo "left behind: $file"; left=1; fi
done
if [[ -d $root/usr/lib/python3/dist-packages/ellc ]]; then
  echo "left behind: /usr/lib/python3/dist-packages/ellc/"; find "$root/usr/lib/python3/dist-packages/ellc"; left=1
fi
((left == 0))

# --- 4. cmake --install into the clean root's /usr/local ----------------------------------------
# The Depends and Recommends installed above stay; no PYTHONPATH or PKG_CONFIG_PATH is set.
echo "== DESTDIR=$root cmake --install $build --prefix /usr/local"
DESTDIR=$root cmake --install "$build" --prefix /usr/local >/dev/null
echo "== checks in the clean root against /usr/local"
in_root env PATH=/usr/local/bin:/usr/bin:/bin ELLC_EXAMPLES=/usr/local/share/ellc/examples \
  ELLC_EXPECT_PYTHONDIR=/usr/local/lib/python3/dist-packages OMPI_ALLOW_RUN_AS_ROOT=1 \
  OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ELLC_CHECK_DEV=yes ELLC_CONSUMER=/tmp/paper_case2.cpp bash -c "$checks"
echo "== check_deb: $(basename "$deb") installs into a clean Debian $suite and works, purge removes it;"
echo "   cmake --install --prefix /usr/local works there too"
# The root is kept after a failure, for a look inside (chroot BUILD_DIR/deb-check/root).
cleanup
rm -rf --one-file-system "$root"

#!/bin/sh
# check_install.sh: the installed boltnet is usable by another project.
#
# Requirement: `cmake --install` into any prefix gives a package that a C program finds
#   (a) through pkg-config alone (boltnet.pc, PKG_CONFIG_PATH=<prefix>/<libdir>/pkgconfig), and
#   (b) through CMake alone (find_package(boltnet) with CMAKE_PREFIX_PATH=<prefix>, boltnet::boltnet,
#       from a C-only project),
# each time building test/test_api.c against the installed header and library (never the build
# tree's) and running it on 1 rank; and
#   (c) the installed plugin and driver load the installed libboltnet (the prefix need not be the
#       CMAKE_INSTALL_PREFIX the build was configured with), and a PETSc-only program
#       (foreign_snes, when given) gets the boltnet line search from the installed plugin;
#   (d) the installed package reproduces README.md: every file of share/scenes, the user scripts,
#       the identify example curves and the docs are installed (docs/install.md), the driver finds
#       an installed scene by its name, and the commands of the README's "Running scenes" block,
#       read from README.md and moved to the installed paths as docs/install.md says (build/bin/ ->
#       <prefix>/bin/, scripts/ -> <prefix>/share/boltnet/scripts/, share/scenes/ ->
#       <prefix>/share/boltnet/scenes/, share/solvers/ -> <prefix>/share/boltnet/solvers/,
#       test/data/identify/ -> <prefix>/share/boltnet/identify/,
#       /tmp/ -> a temporary directory), run from a directory outside the source tree and write
#       their results and charts.
#
# Usage: check_install.sh BUILD_DIR TEST_API_C [CMAKE [MPIEXEC [LIBDIR [CC [FOREIGN_SNES]]]]]
#   e.g. sh test/check_install.sh build test/test_api.c cmake mpiexec lib cc build/bin/foreign_snes
# Exits non-zero on the first failure; removes its temporary directory in every case.
set -eu

usage="usage: check_install.sh BUILD_DIR TEST_API_C [CMAKE [MPIEXEC [LIBDIR [CC [FOREIGN_SNES]]]]]"
build=${1:?$usage}
src=${2:?$usage}
cmake=${3:-cmake}
mpiexec=${4:-mpiexec}
libdir=${5:-lib}
cc=${6:-cc}
foreign=${7:-}

# Open MPI refuses root without these.
OMPI_ALLOW_RUN_AS_ROOT=1
OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
OMPI_MCA_btl_vader_single_copy_mechanism=none
export OMPI_ALLOW_RUN_AS_ROOT OMPI_ALLOW_RUN_AS_ROOT_CONFIRM OMPI_MCA_btl_vader_single_copy_mechanism
# Nothing from the caller's environment may point at another boltnet.
unset LD_LIBRARY_PATH CMAKE_PREFIX_PATH boltnet_DIR 2>/dev/null || true

build=$(cd "$build" && pwd)
src=$(cd "$(dirname "$src")" && pwd)/$(basename "$src")
tmp=$(mktemp -d "${TMPDIR:-/tmp}/boltnet-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
tmp=$(cd "$tmp" && pwd -P)
trap 'exit 1' HUP INT TERM
prefix=$tmp/prefix

fail() {
  echo "check_install: FAIL: $*" >&2
  exit 1
}

# The library a program loads must be the installed one.
check_links_installed() { # program
  deps=$(ldd "$1") || fail "ldd $1 failed"
  echo "$deps" | grep 'libboltnet' || fail "$1 does not link libboltnet"
  if echo "$deps" | grep -q 'libboltnet.*not found'; then fail "$1 cannot find libboltnet (its RUNPATH does not lead to $prefix/$libdir)"; fi
  lib=$(echo "$deps" | awk '/libboltnet\.so/ { print $3; exit }')
  lib=$(readlink -f "$lib") || fail "$1: libboltnet not found"
  case "$lib" in
  "$prefix"/*) ;;
  *) fail "$1 loads libboltnet from '$lib', not from the installed prefix $prefix" ;;
  esac
}

run_test_api() { # program
  out=$("$mpiexec" -n 1 "$1" -options_left 2>&1) || {
    echo "$out"
    fail "$1 failed"
  }
  echo "$out"
  echo "$out" | grep -q 'test_api: PASS' || fail "$1 did not print its PASS line"
  echo "$out" | grep -q 'There are no unused options' || fail "$1 left options unused"
}

echo "== install into $prefix"
"$cmake" --install "$build" --prefix "$prefix" || fail "cmake --install $build --prefix $prefix"
[ -f "$prefix/include/boltnet.h" ] || fail "boltnet.h is not installed in $prefix/include"
[ -f "$prefix/$libdir/pkgconfig/boltnet.pc" ] || fail "boltnet.pc is not installed in $prefix/$libdir/pkgconfig"
[ -f "$prefix/$libdir/cmake/boltnet/boltnetConfig.cmake" ] || fail "boltnetConfig.cmake is not installed in $prefix/$libdir/cmake/boltnet"

echo "== (a) pkg-config"
PKG_CONFIG_PATH=$prefix/$libdir/pkgconfig
export PKG_CONFIG_PATH
cflags=$(pkg-config --cflags boltnet PETSc) || fail "pkg-config --cflags boltnet PETSc"
libs=$(pkg-config --libs boltnet PETSc) || fail "pkg-config --libs boltnet PETSc"
echo "pkg-config boltnet: prefix=$(pkg-config --variable=prefix boltnet) cflags=$cflags"
incdir=$(pkg-config --variable=includedir boltnet)
[ "$(cd "$incdir" 2>/dev/null && pwd -P)" = "$prefix/include" ] ||
  fail "boltnet.pc names the headers '$incdir', not the installed $prefix/include (boltnet.pc: prefix=$(pkg-config --variable=prefix boltnet))"
mkdir -p "$tmp/pc"
# shellcheck disable=SC2086 # word splitting of the flags is intended
mpicc $cflags "$src" -o "$tmp/pc/test_api" $libs -lm || fail "compiling test_api.c with pkg-config flags"
check_links_installed "$tmp/pc/test_api"
run_test_api "$tmp/pc/test_api"
unset PKG_CONFIG_PATH

echo "== (b) CMake find_package(boltnet)"
mkdir -p "$tmp/consumer" "$tmp/consumer-build"
cp "$src" "$tmp/consumer/test_api.c"
cat >"$tmp/consumer/CMakeLists.txt" <<'EOF'
# A C project that uses the installed boltnet through its CMake package only.
cmake_minimum_required(VERSION 3.18)
project(boltnet_consumer LANGUAGES C)
find_package(boltnet REQUIRED)
message(STATUS "boltnet ${boltnet_VERSION} from ${boltnet_DIR}")
add_executable(test_api test_api.c)
target_link_libraries(test_api PRIVATE boltnet::boltnet m)
EOF
"$cmake" -S "$tmp/consumer" -B "$tmp/consumer-build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER="$cc" -DCMAKE_BUILD_TYPE=RelWithDebInfo ||
  fail "configuring a project with find_package(boltnet) and CMAKE_PREFIX_PATH=$prefix"
grep -q "^boltnet_DIR:PATH=$prefix/" "$tmp/consumer-build/CMakeCache.txt" || fail "find_package(boltnet) did not pick the installed package: $(grep '^boltnet_DIR' "$tmp/consumer-build/CMakeCache.txt")"
"$cmake" --build "$tmp/consumer-build" || fail "building test_api.c against boltnet::boltnet"
check_links_installed "$tmp/consumer-build/test_api"
run_test_api "$tmp/consumer-build/test_api"

echo "== (c) installed plugin and driver"
check_links_installed "$prefix/$libdir/libboltnet_snes.so"
check_links_installed "$prefix/bin/boltnet"
if [ -n "$foreign" ]; then
  out=$("$mpiexec" -n 1 "$foreign" -dll_append "$prefix/$libdir/libboltnet_snes.so" -snes_linesearch_type boltnet -options_left 2>&1) || {
    echo "$out"
    fail "$foreign could not use the installed plugin $prefix/$libdir/libboltnet_snes.so"
  }
  echo "$out"
  echo "$out" | grep -q 'line search type boltnet' || fail "$foreign did not use the boltnet line search"
  echo "$out" | grep -q 'foreign_snes: PASS' || fail "$foreign did not print its PASS line"
fi

echo "== (d) the README against the installed package"
root=$(cd "$(dirname "$src")/.." && pwd -P)
data=$prefix/share/boltnet
for f in "$root"/share/scenes/*; do
  [ -f "$data/scenes/$(basename "$f")" ] || fail "the scene file share/scenes/$(basename "$f") is not installed in $data/scenes"
done
for f in plot_joints.py plot_fields.py make-plate-grid; do
  [ -x "$data/scripts/$f" ] || fail "scripts/$f is not installed (executable) in $data/scripts"
done
[ -f "$data/scripts/mpienv" ] || fail "scripts/mpienv is not installed in $data/scripts"
for f in "$root"/share/solvers/*; do
  [ -f "$data/solvers/$(basename "$f")" ] || fail "share/solvers/$(basename "$f") is not installed in $data/solvers"
done
[ -f "$data/identify/cyclic.csv" ] || fail "test/data/identify/cyclic.csv is not installed in $data/identify"
docdir=$prefix/share/doc/boltnet
[ -f "$docdir/README.md" ] || fail "README.md is not installed in $docdir"
for f in "$root"/docs/*.md "$root"/docs/images/*; do
  [ -f "$docdir/docs/${f#"$root"/docs/}" ] || fail "docs/${f#"$root"/docs/} is not installed in $docdir/docs"
done

work=$tmp/work # outside the source tree: nothing there can be found by a relative path
mkdir -p "$work"
cd "$work"
# By name: a scene that only the installed directory has proves where the driver looks.
for f in "$data"/scenes/fig3c.*; do cp "$f" "$data/scenes/installed-only${f#"$data"/scenes/fig3c}"; done
sed -i 's/name: fig3c$/name: installed-only/' "$data/scenes/installed-only.yaml"
out=$("$prefix/bin/boltnet" -scene installed-only -load_steps 6 -output_fields false 2>&1) || {
  echo "$out"
  fail "$prefix/bin/boltnet -scene installed-only did not find the scene in $data/scenes"
}
grep -q '"status": "converged"' results/installed-only/summary.json || fail "the run of the installed scene by name did not converge"
# The plot of fig3b's load shares in the README needs a fig3b run (the README's build made one).
"$prefix/bin/boltnet" -scene fig3b -load_steps 6 >fig3b.log 2>&1 || {
  cat fig3b.log
  fail "$prefix/bin/boltnet -scene fig3b failed"
}

# The "Running scenes" block: the fenced sh block of README.md that runs the default scene.
awk '/^```sh/ { inblock = 1; block = ""; next }
     /^```/ && inblock { inblock = 0; if (block ~ /-scene share\/scenes\/fig3c.yaml/) { printf "%s", block; exit } ; next }
     inblock { block = block $0 "\n" }' "$root/README.md" >readme-block.txt
[ -s readme-block.txt ] || fail "README.md has no sh block that runs -scene share/scenes/fig3c.yaml"
# One command a line (continuations joined, comments dropped), moved to the installed paths.
sed -e ':a' -e '/\\$/N; s/\\\n */ /; ta' readme-block.txt | sed -e 's/[[:space:]]#.*$//' -e '/^[[:space:]]*#/d' -e '/^[[:space:]]*$/d' |
  sed -E -e "s#(^|[[:space:]])/tmp/#\1$tmp/#g" \
    -e "s#(^|[[:space:]])build/bin/#\1$prefix/bin/#g" -e "s#(^|[[:space:]])scripts/#\1$data/scripts/#g" \
    -e "s#(^|[[:space:]])share/scenes/#\1$data/scenes/#g" -e "s#(^|[[:space:]])share/solvers/#\1$data/solvers/#g" \
    -e "s#(^|[[:space:]])test/data/identify/#\1$data/identify/#g" >readme-commands.sh
n=$(wc -l <readme-commands.sh)
[ "$n" -ge 5 ] || fail "only $n commands in README.md's Running scenes block"
if grep -n "$root" readme-commands.sh; then fail "a README command names the source tree"; fi
# mpienv is bash; the commands run in one shell, one after the other, as a reader pastes them.
{
  echo 'set -ex'
  cat readme-commands.sh
} >readme-run.sh
bash readme-run.sh >readme.log 2>&1 || {
  tail -40 readme.log
  fail "a command of README.md failed against the installed package (readme-run.sh above)"
}
grep -q '"status": "converged"' results/fig3c/summary.json || fail "README: results/fig3c/summary.json does not say converged"
grep -q '"status": "converged"' "$tmp/mu02/summary.json" || fail "README: the -output_dir /tmp/mu02 run did not converge"
for png in jump.png law.png share.png; do
  [ -s "$png" ] || fail "README: $png was not written"
done
grep -q '^fit:' readme.log || fail "README: boltnet-identify -curve printed no fit"
echo "ran the $n commands of README.md's Running scenes block against $prefix, from $work"
cd "$tmp"

echo "check_install: PASS"

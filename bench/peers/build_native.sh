#!/usr/bin/env bash
# LAMMPS and LIGGGHTS built for this processor (-O3 -march=native), from the Debian source
# packages of the very versions that bench/compare.sh runs as Debian binaries, so that the
# comparison with riprap (built with target-cpu=native) can be made compiler flags alike.
#
# Usage:  bash bench/peers/build_native.sh        (from anywhere; once: about 30 to 60 min on
#                                                  2 cores, then a second: the result is kept
#                                                  and only checked again)
# Result: $CACHE/bin/lmp-native       LAMMPS 20220106.git7586adbb6a+ds1-2 (bookworm `lammps`),
#                                     CMake, packages GRANULAR only (B1 and B2 need no other),
#                                     MPI (Open MPI) on, OpenMP off, Release
#         $CACHE/bin/liggghts-native  LIGGGHTS-PUBLIC 3.8.0+repack1-9 (bookworm `liggghts`),
#                                     src/Makefile.mpi, without VTK
#         $CACHE/build-info.txt       versions, compilers and flags of both
# A binary that exists already is not rebuilt (delete it, or the cache, to rebuild).
#
# Env: CACHE       cache folder (default: runs/peers-native in the repository; git-ignored)
#      OPT_FLAGS   compiler flags of both builds (default "-O3 -march=native")
#      JOBS        parallel compile jobs (default 2); every compile runs under nice -n 19
#      BUILD       which to build (default "lammps liggghts"; one of them alone, e.g. to build
#                  both at once in two calls)
# Steps (through sudo when not root): if apt-get source has no deb-src URIs, adds
# /etc/apt/sources.list.d/riprap-deb-src.sources (deb-src, bookworm main) and runs apt-get update;
# installs cmake g++ make libopenmpi-dev openmpi-bin dpkg-dev; apt-get source lammps=VERSION
# liggghts=VERSION into $CACHE/src (with Debian's patches applied; where the Debian part cannot
# be fetched, the upstream *.orig.tar.* that apt-get did fetch, without them, and a warning);
# builds; checks each binary, also when it was built before: -h, and two spheres in contact for
# 10 steps (LAMMPS: B2's gran/hooke/history and B1's granular; LIGGGHTS: B1's gran model hertz
# tangential history).
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
CACHE=${CACHE:-$ROOT/runs/peers-native}
OPT_FLAGS=${OPT_FLAGS:-"-O3 -march=native"}
JOBS=${JOBS:-2}
BUILD=${BUILD:-"lammps liggghts"}
LAMMPS_VERSION=20220106.git7586adbb6a+ds1-2
LIGGGHTS_VERSION=3.8.0+repack1-9
mkdir -p "$CACHE/bin" "$CACHE/src"
CACHE=$(cd "$CACHE" && pwd)
LMP=$CACHE/bin/lmp-native
LIG=$CACHE/bin/liggghts-native
NICE=(nice -n 19)
SUDO=()
[ "$(id -u)" -eq 0 ] || SUDO=(sudo)

# ---- tools and sources (only when something is to be built) ------------------------------
if [ -x "$LMP" ] && [ -x "$LIG" ]; then
  echo "== both native peers are built already (delete them, or $CACHE, to rebuild)"
else
  has_deb_src() {
    grep -rqsE '^\s*(Types:.*deb-src|deb-src\s)' /etc/apt/sources.list /etc/apt/sources.list.d/
  }
  if ! has_deb_src; then
    echo "== adding deb-src (bookworm main): /etc/apt/sources.list.d/riprap-deb-src.sources"
    printf '%s\n' "Types: deb-src" "URIs: http://deb.debian.org/debian" "Suites: bookworm" \
      "Components: main" "Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg" \
      | "${SUDO[@]}" tee /etc/apt/sources.list.d/riprap-deb-src.sources > /dev/null
    "${SUDO[@]}" apt-get update -q
  fi
  TOOLS=(cmake g++ make libopenmpi-dev openmpi-bin dpkg-dev)
  missing=()
  for p in "${TOOLS[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2> /dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "== installing ${missing[*]}"
    "${SUDO[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}" \
      || { "${SUDO[@]}" apt-get update -q && "${SUDO[@]}" apt-get install -y -q \
             --no-install-recommends "${missing[@]}"; }
  fi
fi

fetch() {  # fetch PACKAGE VERSION: unpacked source folder on stdout
  # apt-get source unpacks the upstream tarball and applies Debian's patches. Where the Debian
  # part (*.debian.tar.xz) cannot be fetched but the upstream one was (it happened with liggghts
  # 3.8.0+repack1-9: 404 from deb.debian.org), the upstream tarball is unpacked alone, and said so.
  local pkg=$1 ver=$2 dir orig
  dir=$(find "$CACHE/src" -mindepth 1 -maxdepth 1 -type d -name "${pkg}-*" | head -1)
  if [ -z "$dir" ] && [ -d "$CACHE/src/orig-$pkg" ]; then
    dir=$(find "$CACHE/src/orig-$pkg" -mindepth 1 -maxdepth 1 -type d | head -1)
  fi
  if [ -z "$dir" ]; then
    ( cd "$CACHE/src" && apt-get source -q "$pkg=$ver" >&2 ) || true
    dir=$(find "$CACHE/src" -mindepth 1 -maxdepth 1 -type d -name "${pkg}-*" | head -1)
  fi
  if [ -z "$dir" ]; then
    orig=$(find "$CACHE/src" -maxdepth 1 -name "${pkg}_${ver%-*}.orig.tar.*" | head -1)
    [ -n "$orig" ] || { echo "!! apt-get source $pkg=$ver failed" >&2; exit 1; }
    echo "!! apt-get source $pkg=$ver could not fetch or unpack Debian's part; using" \
      "$(basename "$orig") without Debian's patches" >&2
    mkdir -p "$CACHE/src/orig-$pkg" && tar -xf "$orig" -C "$CACHE/src/orig-$pkg"
    dir=$(find "$CACHE/src/orig-$pkg" -mindepth 1 -maxdepth 1 -type d | head -1)
  fi
  [ -n "$dir" ] || { echo "!! no source folder for $pkg in $CACHE/src" >&2; exit 1; }
  [ -d "$dir/debian/patches" ] && echo "   $pkg: $dir (Debian's patches applied)" >&2
  echo "$dir"
}

T0=$SECONDS
# ---- LAMMPS -----------------------------------------------------------------------------
if [ -x "$LMP" ]; then
  echo "== $LMP exists, not rebuilt"
elif [[ " $BUILD " != *" lammps "* ]]; then
  echo "== LAMMPS not asked for (BUILD=$BUILD)"
else
  LSRC=$(fetch lammps "$LAMMPS_VERSION")
  echo "== building LAMMPS from $LSRC (CMake, GRANULAR, MPI, Release, $OPT_FLAGS)"
  t=$SECONDS
  B=$CACHE/build-lammps
  "${NICE[@]}" cmake -S "$LSRC/cmake" -B "$B" -D CMAKE_BUILD_TYPE=Release \
    -D CMAKE_CXX_FLAGS_RELEASE="$OPT_FLAGS" -D CMAKE_C_FLAGS_RELEASE="$OPT_FLAGS" \
    -D BUILD_MPI=on -D BUILD_OMP=off -D BUILD_SHARED_LIBS=off -D PKG_GRANULAR=on \
    -D LAMMPS_EXCEPTIONS=off -D WITH_JPEG=off -D WITH_PNG=off -D WITH_GZIP=on \
    -D WITH_FFMPEG=off -D BUILD_TOOLS=off -D BUILD_DOC=off > "$CACHE/lammps-cmake.log" 2>&1 \
    || { tail -30 "$CACHE/lammps-cmake.log"; exit 1; }
  "${NICE[@]}" cmake --build "$B" -j "$JOBS" > "$CACHE/lammps-build.log" 2>&1 \
    || { tail -30 "$CACHE/lammps-build.log"; exit 1; }
  install -m 755 "$B/lmp" "$LMP"
  LMP_TIME=$((SECONDS - t))
  echo "== LAMMPS built in ${LMP_TIME} s"
  { echo "lmp-native: lammps $LAMMPS_VERSION ($LSRC)"
    echo "  built $(date -u +%Y-%m-%dT%H:%MZ) in ${LMP_TIME} s, $(c++ --version | head -1)"
    echo "  cmake -D CMAKE_BUILD_TYPE=Release -D CMAKE_CXX_FLAGS_RELEASE='$OPT_FLAGS'" \
         "-D CMAKE_C_FLAGS_RELEASE='$OPT_FLAGS' -D BUILD_MPI=on -D BUILD_OMP=off -D PKG_GRANULAR=on"
    grep -E '^(CMAKE_CXX_COMPILER|MPI_CXX_COMPILER|CMAKE_CXX_FLAGS_RELEASE):' "$B/CMakeCache.txt" \
      | sed 's/^/  /'
  } > "$CACHE/lammps-info.txt"
fi

# ---- LIGGGHTS ---------------------------------------------------------------------------
if [ -x "$LIG" ]; then
  echo "== $LIG exists, not rebuilt"
elif [[ " $BUILD " != *" liggghts "* ]]; then
  echo "== LIGGGHTS not asked for (BUILD=$BUILD)"
else
  GSRC=$(fetch liggghts "$LIGGGHTS_VERSION")
  echo "== building LIGGGHTS from $GSRC (src/Makefile.mpi, no VTK, $OPT_FLAGS)"
  t=$SECONDS
  # A copy of src/, so that the unpacked source stays as it came; an interrupted build goes on
  # where it stopped.
  B=$CACHE/build-liggghts
  [ -d "$B/src" ] || { mkdir -p "$B" && cp -a "$GSRC/src" "$B/src"; }
  # GCC 12 rejects two lines of LIGGGHTS 3.8.0 (what Debian's patches mend, where they could
  # not be applied): utils.h's int_to_string static_casts the rvalue stream that operator<<
  # returns (now a named ostringstream), and finish.cpp compares a pointer with 0 by > (now
  # a test for null, as later LAMMPS has it). Both edits are idempotent.
  sed -i 's/return static_cast< std::ostringstream & >(( std::ostringstream() << std::dec << a ) ).str();/std::ostringstream ss; ss << std::dec << a; return ss.str();/' \
    "$B/src/utils.h"
  sed -i 's/if (neighbor->lists\[m\]->numneigh > 0) {/if (neighbor->lists[m]->numneigh) {/' \
    "$B/src/finish.cpp"
  # Without VTK, LAMMPS_VTK is not defined and the VTK writers compile to nothing, except
  # dump_mesh_vtk.cpp, which includes VTK's headers unguarded: such files (and their header,
  # which registers the dump style) are left out of the copy.
  for f in "$B"/src/*.cpp; do
    if grep -q '#include *<vtk' "$f" && ! grep -q LAMMPS_VTK "$f"; then
      echo "   without VTK: leaving out $(basename "$f" .cpp).{cpp,h}"
      rm -f "$f" "${f%.cpp}.h" "$B/src/Obj_mpi/$(basename "${f%.cpp}").d"
    fi
  done
  # LIGGGHTS' own src/MAKE/Makefile.mpi (mpicxx; its -funroll-loops -fstrict-aliasing kept,
  # -O2 -fPIC replaced by OPT_FLAGS), LMP_INC -DLAMMPS_GZIP without -DLAMMPS_VTK, and VTK_INC,
  # VTK_PATH, VTK_LIB empty. Debian's package is built with CMake (src/CMakeLists.txt) against
  # VTK 9 (its Build-Depends); the styles that B1 runs are the same either way.
  # make -k: a failing file does not stop the others, so that one build shows every error.
  make_vars=(CC=mpicxx LINK=mpicxx "CCFLAGS=$OPT_FLAGS -funroll-loops -fstrict-aliasing"
    "LINKFLAGS=$OPT_FLAGS" "LMP_INC=-DLAMMPS_GZIP" VTK_INC= VTK_PATH= VTK_LIB=)
  "${NICE[@]}" make -k -C "$B/src" -j "$JOBS" mpi "${make_vars[@]}" > "$CACHE/liggghts-build.log" 2>&1 \
    || { grep -E 'error' "$CACHE/liggghts-build.log" | head -30; tail -5 "$CACHE/liggghts-build.log"
         exit 1; }
  install -m 755 "$B/src/lmp_mpi" "$LIG"
  LIG_TIME=$((SECONDS - t))
  echo "== LIGGGHTS built in ${LIG_TIME} s"
  { echo "liggghts-native: liggghts $LIGGGHTS_VERSION ($GSRC)"
    echo "  built $(date -u +%Y-%m-%dT%H:%MZ) in ${LIG_TIME} s (the last call, where an" \
      "interrupted build went on), $(mpicxx --version | head -1)"
    echo "  make -C src mpi ${make_vars[*]}"
  } > "$CACHE/liggghts-info.txt"
fi

# ---- checks -----------------------------------------------------------------------------
echo "== checking the binaries"
CHK=$CACHE/check
mkdir -p "$CHK"
if [ -x "$LMP" ]; then
"$LMP" -h > "$CHK/lmp-h.txt" 2>&1 || { echo "!! $LMP -h failed"; exit 1; }
grep -qiE 'GRANULAR' "$CHK/lmp-h.txt" || { echo "!! $LMP: no GRANULAR package"; exit 1; }
# Two touching spheres with B2's pair style and B1's granular style, 10 steps.
cat > "$CHK/in.lmp" << 'EOF'
units lj
atom_style sphere
boundary p p p
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 single 1 1 1
create_atoms 1 single 1.95 1 1
set type 1 diameter 1.0
set type 1 density 1.0
comm_modify vel yes
pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
run 10
pair_style granular
pair_coeff * * hertz/material 5e6 0.36665136 0.3 damping tsuji tangential mindlin 4524886.878 0.90748521 0.5
run 10
EOF
( cd "$CHK" && "$LMP" -in in.lmp -log none > lmp-run.txt 2>&1 ) \
  && grep -q "Loop time" "$CHK/lmp-run.txt" || { echo "!! $LMP: tiny run failed ($CHK/lmp-run.txt)"; exit 1; }
echo "   lmp-native: -h and a tiny run (gran/hooke/history, granular) ok"
fi
if [ -x "$LIG" ]; then
( cd "$CHK" && "$LIG" -h > lig-h.txt 2>&1 ) || true
grep -qiE 'LIGGGHTS' "$CHK/lig-h.txt" || { echo "!! $LIG -h failed ($CHK/lig-h.txt)"; exit 1; }
cat > "$CHK/in.lig" << 'EOF'
atom_style granular
atom_modify map array
boundary p p p
newton off
communicate single vel yes
units si
region box block 0 0.04 0 0.04 0 0.04 units box
create_box 1 box
neighbor 0.002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 3.0e-5
create_atoms 1 single 0.01 0.01 0.01 units box
create_atoms 1 single 0.0199 0.01 0.01 units box
set atom * diameter 0.01 density 2500
fix integr all nve/sphere
run 10
EOF
( cd "$CHK" && "$LIG" -in in.lig -log none > lig-run.txt 2>&1 ) \
  && grep -q "Loop time" "$CHK/lig-run.txt" || { echo "!! $LIG: tiny run failed ($CHK/lig-run.txt)"; exit 1; }
echo "   liggghts-native: -h and a tiny run (gran model hertz tangential history) ok"
fi

cat "$CACHE"/lammps-info.txt "$CACHE"/liggghts-info.txt > "$CACHE/build-info.txt" 2> /dev/null || true
echo "== built (total $((SECONDS - T0)) s this call):"
cat "$CACHE/build-info.txt"

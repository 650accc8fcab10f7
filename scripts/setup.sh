# Shared set-up for the README's two commands (sourced, not run): install what is
# missing from Debian 12's packages, then configure and build the release preset.
#
#   source scripts/setup.sh run    what running the labs needs (scripts/run-labs): the
#                                  labs, rigidlab, the explorer, their man pages; the
#                                  build without the tests and the bench
#   source scripts/setup.sh test   that and what testing needs (scripts/run-tests, the
#                                  sanitizers, the explorer's screenshots; the default)
#
# Set-up with nothing to do costs nothing: the package check is skipped while its
# stamp is newer than this file, and the configure step while the build directory
# exists (the build re-runs CMake itself when a CMakeLists.txt changes); a build first
# made for running gains the tests and the bench when testing asks for them.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
rigid_setup="${1:-test}"
case "$rigid_setup" in
  run | test) ;;
  *) echo "scripts/setup.sh: unknown set-up '$rigid_setup' (run or test)" >&2; exit 2 ;;
esac

# To build and run: the compilers and CMake (Python runs at configure time and for
# the errata sheet), the physics' libraries, the renderer's (OSMesa, EGL, PNG,
# FreeType and the font, cairo for the plots and the SVG and PDF figures, WebP and
# FFmpeg for --animate), the explorer's (GLFW, Dear ImGui), pybind11, Python's headers
# and NumPy for `import rigidlab`, and help2man for the man pages `cmake --install`
# puts beside the programs.
RIGID_RUN_PACKAGES=(
  build-essential cmake ninja-build pkg-config python3
  libeigen3-dev libboost-dev libcli11-dev nlohmann-json3-dev libfmt-dev
  libosmesa6-dev libegl-dev libegl1-mesa-dev libgl-dev libpng-dev libfreetype-dev fonts-dejavu-core
  libcairo2-dev libwebp-dev libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
  libglfw3-dev libimgui-dev pybind11-dev python3-dev python3-numpy help2man
)
# To test: Catch2; Python's numbers for the references, the schema check and the
# bench's peers (with GSL's); Xvfb, xauth and xdotool for the explorer under a display
# server; librsvg and poppler to read back the SVG and PDF figures; clang-format and
# pmccabe for scripts/check-format and check-size; emscripten (with node) for the
# wasm test; file for cpack's dpkg-shlibdeps (the package test); pytest, nbconvert and
# ipykernel for the Python module's tests and its worked notebook; pandas and R
# (r-base-core) for the test that the readers students use take a lab's CSV whole;
# Chromium (and npm, for puppeteer-core, where node came without it) for the web page's.
RIGID_TEST_PACKAGES=(
  catch2 libgsl-dev
  python3-scipy python3-matplotlib python3-mpmath python3-jsonschema python3-pytest
  jupyter-nbconvert python3-ipykernel python3-pandas r-base-core
  xvfb xauth xdotool librsvg2-bin poppler-utils
  clang-format pmccabe emscripten file chromium
)
command -v npm >/dev/null || RIGID_TEST_PACKAGES+=(npm)
packages=("${RIGID_RUN_PACKAGES[@]}")
[ "$rigid_setup" = test ] && packages+=("${RIGID_TEST_PACKAGES[@]}")

stamp=build/.packages-$rigid_setup
if [ ! -f "$stamp" ] || [ scripts/setup.sh -nt "$stamp" ]; then
  missing=()
  for package in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$package")
  done
  if ((${#missing[@]})); then
    echo "rigidlab: installing ${missing[*]}"
    sudo_cmd=()
    [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
      "${missing[@]}" >/dev/null
  fi
fi

# A build directory from an older generator is made anew; one made for running gains
# the tests and the bench when testing asks for them.
# In CI (CI=true) the project's own sources build with -Werror.
suite=ON
[ "$rigid_setup" = run ] && suite=OFF
if [ ! -f build/build.ninja ]; then
  rm -rf build
  werror=OFF
  [ "${CI:-}" = true ] && werror=ON
  cmake --preset release -DRIGID_WERROR=$werror -DRIGID_BUILD_TESTS=$suite \
    -DRIGID_BUILD_BENCH=$suite >/dev/null
elif [ "$suite" = ON ] && grep -q '^RIGID_BUILD_\(TESTS\|BENCH\):BOOL=OFF' build/CMakeCache.txt; then
  cmake build -DRIGID_BUILD_TESTS=ON -DRIGID_BUILD_BENCH=ON >/dev/null
fi
mkdir -p build && touch "$stamp"
[ "$rigid_setup" = test ] && touch build/.packages-run  # testing's packages hold running's
cmake --build --preset release -j "$(nproc)" | { grep -v '^ninja: no work to do' || true; }

# Shared set-up for the two README commands (sourced, not run): install what is
# missing from Debian 12's packages, then configure and build the release
# preset. Set-up with nothing to do costs nothing: the package check is skipped
# while its stamp is newer than this file, and the configure step while the
# build directory exists (the build re-runs CMake itself when a CMakeLists.txt
# changes).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

RIGID_PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libboost-dev libcli11-dev nlohmann-json3-dev libfmt-dev catch2
  libosmesa6-dev libegl-dev libegl1-mesa-dev libgl-dev libpng-dev libfreetype-dev fonts-dejavu-core
  libgsl-dev python3-scipy python3-matplotlib python3-mpmath python3-jsonschema help2man
  libwebp-dev libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
  libglfw3-dev libimgui-dev xvfb xauth xdotool
  libcairo2-dev librsvg2-bin poppler-utils
  clang-format pmccabe emscripten file
)

stamp=build/.packages-installed
if [ ! -f "$stamp" ] || [ scripts/setup.sh -nt "$stamp" ]; then
  missing=()
  for package in "${RIGID_PACKAGES[@]}"; do
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

# A build directory from an older generator is made anew.
# In CI (CI=true) the project's own sources build with -Werror.
if [ ! -f build/build.ninja ]; then
  rm -rf build
  werror=OFF
  [ "${CI:-}" = true ] && werror=ON
  cmake --preset release -DRIGID_WERROR=$werror >/dev/null
fi
mkdir -p build && touch "$stamp"
cmake --build --preset release -j "$(nproc)" | { grep -v '^ninja: no work to do' || true; }

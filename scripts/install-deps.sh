#!/usr/bin/env bash
# Installs every build and test dependency from Debian 12 packages. Safe to re-run.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
packages=(
  build-essential cmake ninja-build pkg-config git
  ccache                              # one compiler cache for the nested builds of CI and the grader
  clang-format                        # Format.ClangFormat: the code style CI enforces
  libglm-dev                # vector math
  libpcg-cpp-dev            # stage 10: the PCG random generators (pcg_random.hpp), header only
  libpng-dev libopenexr-dev # PNG and EXR in and out (fast process start)
  libopenimageio-dev        # every other image format, loaded on first use
  nlohmann-json3-dev        # scene files
  libcli11-dev              # command lines
  libtinyobjloader-dev      # OBJ meshes
  libgtest-dev libgmock-dev # unit tests
  libxxhash-dev             # rt-grade: the judge names a scene the worker holds by its hash
  libcgal-dev libgmp-dev libmpfr-dev  # exact predicates in the tests
  libglfw3-dev libosmesa6-dev         # GL contexts (windowed, headless)
  libegl-dev libegl-mesa0 libepoxy-dev # headless EGL contexts, GL function loading
  libimgui-dev                        # rt view: Dear ImGui with its GLFW and OpenGL 3 back-ends
  xvfb xauth                          # View.ScriptedSession: the viewer's window under Xvfb
  glslang-tools                       # stage 09: glslangValidator checks every shader offline
  chromium                            # Gallery.IndexPage: the gallery page in a headless browser
  libembree-dev                       # rt-bench: Embree 3, the BVH benchmark's yardstick (optional)
  zip unzip                           # rt-grade: .zip submissions, the Gradescope package
  patchelf                            # rt-grade package: the bundle finds its libraries by $ORIGIN
  util-linux procps                   # rt-grade's tests: setpriv/pgrep checks of the sandbox
  libseccomp-dev                      # rt-grade: the seccomp filter of its container mode
  jq openimageio-tools                # rt-grade's tests: grading.json lists, 8-bit images without sRGB
  similarity-tester                   # rt-grade similarity: sim_c++ and sim_text compare submissions
  libyaml-cpp-dev                     # rt-grade batch: Gradescope exports' submission_metadata.yml
  hyperfine                           # tools/bench_startup.sh, tools/bench_povray.sh: timings
  povray                              # tools/bench_povray.sh: POV-Ray 3.7, the renderer's yardstick
  slurm-wlm munge                     # Grader.Slurm.class: rt-grade batch --slurm on a one-machine cluster
)
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null
# Web.ExportMatchesCpu drives Chromium with puppeteer-core (tools/web/). Debian's nodejs and npm
# unless a node with npm is already there (NodeSource's nodejs bundles npm and conflicts with it).
if ! command -v npm > /dev/null || ! command -v node > /dev/null; then
  $SUDO apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null
fi
(cd "$(dirname "$0")/../tools/web" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
echo "install-deps: all packages present, tools/web's node modules installed"

#!/usr/bin/env bash
# Installs the Debian packages zblend needs, only those missing. Quiet when all are present.
# Usage: setup.sh [run|test|kit|synth|profile|bench|view]
#   run:     what `make run` needs to build zblend and render: a compiler, CMake, Verilator and
#            the libraries zblend links (GLM, stb, CLI11, nlohmann-json, fmt, OpenSSL's
#            libcrypto for the conformance signatures' SHA-256, zlib for the PNG writer's
#            deflate and Verilator's FST, tinyobjloader, tinygltf).
#   test:    (the default) run's, and what `make test` and the other targets use: GoogleTest and
#            Google Benchmark; Icarus Verilog (the RTL's second simulator, the conformance kit);
#            SystemC; clang (libFuzzer, LeakSanitizer's runtime); the test scenes; OpenGL on
#            Mesa (the oracle); matplotlib (the lab's charts); Yosys, yosys-smtbmc and z3 (the
#            CI-sized formal proofs and mutants); GNU parallel, Slurm and munge, OpenSSH's
#            server and iproute2 (the regression runner's tests, docs/regressions.md: the ssh
#            test starts its own sshds in network namespaces); GTKWave and Xvfb (the waves'
#            test).
#   kit:     what `make kit` needs to build the conformance kit alone: run's without Verilator,
#            and Python 3 with NumPy (the kit's Python module, conformance/python).
#   synth:   test's, and nextpnr-ice40 and IceStorm (`make synth`).
#   profile: test's, and perf (`make profile-rtl`).
#   bench:   test's, and valgrind (`make bench`: the RTL's instructions per simulated cycle,
#            counted, beside a baseline build).
#   view:    test's, and Chromium and ImageMagick (HTML reports and waves, headless, screenshots).
# A system sshd that the openssh-server package starts on install is stopped and disabled again:
# nothing here needs it, and this machine should not gain an open ssh port from a setup script.
set -euo pipefail

group=${1:-test}
packages=(
  build-essential cmake make
  libglm-dev libstb-dev libcli11-dev nlohmann-json3-dev libfmt-dev libssl-dev zlib1g-dev
  libtinyobjloader-dev libtinygltf-dev
)
if [[ $group != kit ]]; then
  packages+=(verilator)
fi
if [[ $group != run && $group != kit ]]; then
  packages+=(
    libgtest-dev libbenchmark-dev
    iverilog libsystemc-dev
    clang libclang-rt-14-dev
    assimp-testmodels glmark2-data
    libegl-dev libgl-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri
    python3-matplotlib
    yosys z3
    parallel slurm-wlm munge openssh-server openssh-client iproute2
    gtkwave xvfb xauth
  )
fi
case $group in
  run | test) ;;
  kit) packages+=(python3 python3-numpy) ;;
  synth) packages+=(nextpnr-ice40 fpga-icestorm) ;;
  profile) packages+=(linux-perf) ;;
  bench) packages+=(valgrind) ;;
  view) packages+=(chromium imagemagick) ;;
  *)
    echo "setup: error: unknown group '$group' (choose run, test, kit, synth, profile, bench or view)" >&2
    exit 2
    ;;
esac

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ $status == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "setup: installing ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "setup: error: missing packages (${missing[*]}) and not root; run 'apt-get install ${missing[*]}' as root" >&2
  exit 2
fi
# The package's postinst starts and enables ssh.service where it can (under systemd, or sysv init
# without a policy-rc.d that refuses). Undo that: we installed it only for its sshd binary.
no_system_sshd() {
  if [[ -d /run/systemd/system ]]; then
    "${sudo[@]}" systemctl disable --now ssh.service ssh.socket >/dev/null 2>&1 || true
  elif [[ -x /etc/init.d/ssh ]]; then
    "${sudo[@]}" /etc/init.d/ssh stop >/dev/null 2>&1 || true
    "${sudo[@]}" update-rc.d ssh disable >/dev/null 2>&1 || true
  fi
  if [[ -s /run/sshd.pid ]] && kill -0 "$(cat /run/sshd.pid)" 2>/dev/null; then
    echo "setup: warning: a system sshd still runs (/run/sshd.pid); nothing here uses it" >&2
  fi
}
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
[[ " ${missing[*]} " == *" openssh-server "* ]] && no_system_sshd
echo "setup: done"

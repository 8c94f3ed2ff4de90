#!/usr/bin/env bash
# Installs the Debian packages zblend needs, only those missing. Quiet when all are present.
# Usage: setup.sh [synth|profile|view]   (synth: also nextpnr-ice40 and IceStorm, for `make
# synth`; profile: also perf, for `make profile-rtl`; view: Chromium and ImageMagick, to look at
# HTML reports and waves headless and take screenshots). Always in: Yosys, its yosys-smtbmc and
# z3 (`make test` runs the CI-sized `make formal`); GNU parallel, Slurm and munge, and OpenSSH's
# server and iproute2 (the regression runner's tests, docs/regressions.md: the ssh test starts its
# own sshds in network namespaces, scripts/ssh_hosts.sh); GTKWave and Xvfb (the waves' test);
# Icarus Verilog (the RTL's second simulator, docs/rtl.md "Simulators"; the conformance kit);
# OpenSSL's libcrypto (the conformance signatures' SHA-256).
# A system sshd that the openssh-server package starts on install is stopped and disabled again:
# nothing here needs it, and this machine should not gain an open ssh port from a setup script.
set -euo pipefail

packages=(
  build-essential cmake make
  libglm-dev libstb-dev libcli11-dev nlohmann-json3-dev libfmt-dev libssl-dev
  libgtest-dev libbenchmark-dev
  verilator iverilog zlib1g-dev libsystemc-dev
  clang libclang-rt-14-dev
  libtinyobjloader-dev libtinygltf-dev assimp-testmodels glmark2-data
  libegl-dev libgl-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri
  python3-matplotlib
  yosys z3
  parallel slurm-wlm munge openssh-server openssh-client iproute2
  gtkwave xvfb xauth
)
if [[ ${1:-} == synth ]]; then
  packages+=(nextpnr-ice40 fpga-icestorm)
elif [[ ${1:-} == profile ]]; then
  packages+=(linux-perf)
elif [[ ${1:-} == view ]]; then
  packages+=(chromium imagemagick)
elif [[ $# -gt 0 ]]; then
  echo "setup: error: unknown group '$1' (choose synth, profile or view)" >&2
  exit 2
fi

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

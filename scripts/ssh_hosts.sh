#!/usr/bin/env bash
# Test hosts on this machine for the regression runner's GNU parallel path over ssh
# (docs/regressions.md). Each host is a network namespace of its own, joined to this one by a veth
# pair in a /30 of 10.213.0.0/16 that no interface or route here uses yet, and runs its own sshd
# bound to the namespace's address only, root login by key. Everything lives in DIR: host and user
# keys, sshd_config, ssh_config, known_hosts, the sshds' pid files and logs, and sshloginfile in GNU
# parallel's format; nothing under /etc/ssh or ~/.ssh is read or written. The namespaces share this
# machine's file system, which stands in for the shared file system the runner needs.
#   ssh_hosts.sh start DIR [N]   starts N hosts (default 1); prints DIR/sshloginfile. A DIR left
#                                by a killed run is stopped and cleaned first.
#   ssh_hosts.sh stop DIR        stops the sshds, deletes the namespaces and veths; exit 1 if any
#                                of them is left
# Needs root, OpenSSH's server and iproute2 (scripts/setup.sh). Exit 2 on bad usage.
set -euo pipefail

SSHD=/usr/sbin/sshd  # sshd re-executes itself, so it wants its absolute path
NET=10.213           # the hosts' /30s are 10.213.X.0/30, X in 1..254: host X.2, this side X.1
MAX_HOSTS=32

usage() {
  echo "usage: $(basename "$0") start DIR [N] | stop DIR   (N hosts, 1 to $MAX_HOSTS; default 1)" >&2
  exit 2
}
say() { echo "ssh_hosts: $*" >&2; }

[[ $# -ge 2 ]] || usage
action=$1
dir=$(realpath -m "$2")
hosts=$dir/hosts  # one line per host as it is made: index, namespace, veth, address
case $action in
  start) [[ $# -le 3 ]] || usage; n=${3:-1} ;;
  stop) [[ $# -eq 2 ]] || usage ;;
  *) usage ;;
esac

ns_exists() { [[ -e /run/netns/$1 ]]; }  # where ip netns keeps its names

# alive PID...: one of them runs. A zombie does not count: this machine's init may take seconds
# to reap the sshd it inherited.
alive() {
  local p st
  for p in "$@"; do
    st=$(sed 's/.*) //' "/proc/$p/stat" 2>/dev/null) || continue
    [[ ${st%% *} == Z ]] || return 0
  done
  return 1
}

# kill_ns NS PIDFILE: every process in the namespace (the sshd and any session it forked), TERM
# then KILL. False if one survives.
kill_ns() {
  local ns=$1 pidf=$2 pids=()
  # The pid file's pid only while it is still this DIR's sshd: a stale file's pid may be reused.
  [[ -s $pidf ]] && grep -qF -- "$dir/sshd_config" "/proc/$(cat "$pidf")/cmdline" 2>/dev/null &&
    pids+=("$(cat "$pidf")")
  ns_exists "$ns" && mapfile -t -O "${#pids[@]}" pids < <(ip netns pids "$ns")
  [[ ${#pids[@]} -gt 0 ]] || return 0
  kill "${pids[@]}" 2>/dev/null || true
  for _ in $(seq 30); do
    alive "${pids[@]}" || return 0
    sleep 0.1
  done
  kill -9 "${pids[@]}" 2>/dev/null || true
  sleep 0.2
  ! alive "${pids[@]}"
}

# gone_link LINK: false if the link is still there after 2 s.
gone_link() {
  for _ in $(seq 20); do
    ip link show "$1" >/dev/null 2>&1 || return 0
    sleep 0.1
  done
  return 1
}

stop() {
  local left=() i ns veth addr stray
  if [[ -f $hosts ]]; then
    [[ $(id -u) -eq 0 ]] || { say "needs root"; exit 2; }
    while read -r i ns veth addr; do
      kill_ns "$ns" "$dir/sshd-$i.pid" || left+=("processes in $ns")
      if ns_exists "$ns"; then
        # Deleting the veth pair from inside is synchronous, unlike the kernel's clean-up of a
        # deleted namespace.
        ip -n "$ns" link del zb0 2>/dev/null || true
        ip netns del "$ns" 2>/dev/null || true
      fi
      ns_exists "$ns" && left+=("namespace $ns")
      [[ -z $veth ]] || gone_link "$veth" || left+=("veth $veth")
      rm -f "$dir/sshd-$i.pid"
    done <"$hosts"
  fi
  stray=$(pgrep -f -- "$dir/sshd_config" || true)
  [[ -z $stray ]] || left+=("sshd ${stray//$'\n'/ }")
  if [[ ${#left[@]} -gt 0 ]]; then
    say "still there: ${left[*]}"
    return 1
  fi
  rm -f "$hosts" "$dir/sshloginfile"
}

need() {
  [[ $(id -u) -eq 0 ]] || { say "needs root (namespaces, and sshds that log in as root)"; exit 2; }
  local tool
  for tool in ip nsenter ssh ssh-keygen "$SSHD"; do
    command -v "$tool" >/dev/null ||
      { say "$tool is missing: run scripts/setup.sh (openssh-server, iproute2)"; exit 2; }
  done
  if [[ ! $n =~ ^[0-9]+$ ]] || ((n < 1 || n > MAX_HOSTS)); then usage; fi
  # GNU parallel splits an sshloginfile line at spaces, and the line names DIR/ssh_config.
  [[ $dir != *[[:space:],]* ]] || { say "DIR must not hold spaces or commas: $dir"; exit 2; }
  # Without PAM, sshd refuses every login to an account whose password is locked ('!').
  [[ $(getent shadow root | cut -d: -f2) != '!'* ]] ||
    { say "root's password is locked ('!' in /etc/shadow); sshd without PAM refuses it"; exit 2; }
}

write_configs() {
  ssh-keygen -q -t ed25519 -N '' -C zblend-test-host -f "$dir/host_ed25519"
  ssh-keygen -q -t ed25519 -N '' -C zblend-test-user -f "$dir/id_ed25519"
  cp "$dir/id_ed25519.pub" "$dir/authorized_keys"
  cat >"$dir/sshd_config" <<EOF
# ssh_hosts.sh: the test hosts' sshd; each adds its ListenAddress and PidFile with -o.
HostKey $dir/host_ed25519
AuthorizedKeysFile $dir/authorized_keys
PermitRootLogin prohibit-password
PubkeyAuthentication yes
PasswordAuthentication no
KbdInteractiveAuthentication no
UsePAM no
# DIR may sit under a world-writable /tmp, which strict modes refuse.
StrictModes no
AllowTcpForwarding no
X11Forwarding no
PrintMotd no
PrintLastLog no
# GNU parallel may open many sessions at once (-j per host); the default drops some at 10.
MaxStartups 100
EOF
  cat >"$dir/ssh_config" <<EOF
# ssh_hosts.sh: for the test hosts only (ssh -F $dir/ssh_config root@ADDRESS).
Host *
  IdentityFile $dir/id_ed25519
  IdentitiesOnly yes
  UserKnownHostsFile $dir/known_hosts
  GlobalKnownHostsFile /dev/null
  StrictHostKeyChecking accept-new
  BatchMode yes
  ConnectTimeout 10
  LogLevel ERROR
EOF
}

# free_net X: 10.213.X.0/30 is on no interface, under no route but the default, and its veth
# name is free.
free_net() {
  local x=$1 used routes
  ! ip link show "zbssh$x" >/dev/null 2>&1 || return 1
  used=$(ip -4 -o addr show)
  [[ $used != *" $NET.$x."* ]] || return 1
  routes=$(ip -4 route show match "$NET.$x.2")
  ! grep -qv '^default' <<<"$routes"
}

# add_host I: namespace, veth pair, addresses, sshd; recorded in DIR/hosts before anything
# that could be left behind exists.
add_host() {
  local i=$1 ns x veth="" addr=""
  ns=zbssh-$(head -c 4 /dev/urandom | od -An -tx1 | tr -d ' \n')-$i
  echo "$i $ns" >>"$hosts"
  ip netns add "$ns" ||
    { say "cannot make a network namespace (root with CAP_SYS_ADMIN and CAP_NET_ADMIN needed)"; return 1; }
  for x in $(seq 1 254); do
    free_net "$x" || continue
    # Creating the link claims X; a concurrent start that took it first makes this fail.
    if ip link add "zbssh$x" type veth peer name zb0 netns "$ns" 2>/dev/null; then
      veth=zbssh$x
      break
    fi
    ip link show "zbssh$x" >/dev/null 2>&1 || { say "cannot create a veth pair"; return 1; }
  done
  [[ -n $veth ]] || { say "no free /30 in $NET.0.0/16"; return 1; }
  addr=$NET.$x.2
  sed -i "\$s/.*/$i $ns $veth $addr/" "$hosts"
  ip addr add "$NET.$x.1/30" dev "$veth"
  ip link set "$veth" up
  ip -n "$ns" addr add "$addr/30" dev zb0
  ip -n "$ns" link set zb0 up
  ip -n "$ns" link set lo up
  # sshd's privilege separation directory (built into the binary), root's and 0755 or it refuses.
  [[ -d /run/sshd ]] || install -d -m 0755 /run/sshd
  # nsenter (not ip netns exec) keeps the sshd in this mount namespace: the file system is shared.
  if ! nsenter --net="/run/netns/$ns" -- "$SSHD" -f "$dir/sshd_config" -E "$dir/sshd-$i.log" \
      -o "ListenAddress=$addr" -o "PidFile=$dir/sshd-$i.pid"; then
    say "sshd on $addr did not start:"; tail -5 "$dir/sshd-$i.log" >&2; return 1
  fi
  wait_login "$addr" || { say "sshd's log:"; tail -5 "$dir/sshd-$i.log" >&2; return 1; }
}

# wait_login ADDR: a real login (within 10 s), which also records the host key in
# DIR/known_hosts.
wait_login() {
  local err
  for _ in $(seq 100); do
    err=$(ssh -F "$dir/ssh_config" "root@$1" true 2>&1) && return 0
    sleep 0.1
  done
  say "no login to root@$1: $err"
  return 1
}

if [[ $action == stop ]]; then
  stop
  exit
fi

need
if [[ -f $hosts ]]; then
  say "$dir holds hosts of an earlier run: stopping them"
  stop || exit 1
fi
mkdir -p "$dir"
rm -f "$dir"/{sshloginfile,ssh_config,sshd_config,known_hosts,authorized_keys} \
  "$dir"/{host,id}_ed25519{,.pub} "$dir"/sshd-*.{pid,log}
write_configs
# Whatever stops start half-way (an error, ^C, a TERM) takes down what it made.
on_exit() {
  local rc=$?
  [[ $rc -eq 0 ]] || { say "start failed: stopping what it made"; stop || true; }
}
trap on_exit EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
for i in $(seq "$n"); do
  add_host "$i"
done
# The list is written last, whole: a reader never sees a host that is not up.
while read -r i ns veth addr; do
  echo "1/ssh -F $dir/ssh_config root@$addr"
done <"$hosts" >"$dir/sshloginfile.new"
mv "$dir/sshloginfile.new" "$dir/sshloginfile"
echo "$dir/sshloginfile"

#!/bin/bash
# netns.sh COMMAND [ARGS...]: runs COMMAND in a private network namespace whose
# loopback carries multicast, with LCM_DEFAULT_URL on a ttl=0 udpm group. Tests
# that use udpm run under this, so their traffic never leaves the namespace.
# Needs root (or user namespaces); exits 77 (CTest: skipped) when it cannot
# create the namespace.
set -euo pipefail
if [[ "${DREAM_TEST_NETNS:-}" != "$$" ]]; then
  if ! unshare -n true 2>/dev/null; then
    echo "SKIP: cannot create a private network namespace (unshare -n); udpm tests need root" >&2
    exit 77
  fi
  exec unshare -n bash -c 'export DREAM_TEST_NETNS=$$; exec bash "$0" "$@"' "$0" "$@"
fi
ip link set lo up
ip route add 224.0.0.0/4 dev lo
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
exec "$@"

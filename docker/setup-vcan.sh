#!/usr/bin/env bash
# Create a virtual CAN interface on the host (the containers use the host's network).
#   sudo docker/setup-vcan.sh [NAME]        default vcan0
set -euo pipefail
name=${1:-vcan0}
modprobe vcan
if ! ip link show "$name" >/dev/null 2>&1; then
  ip link add dev "$name" type vcan
fi
ip link set up "$name"
ip -details link show "$name"

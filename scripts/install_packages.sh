#!/usr/bin/env bash
# Installs the Debian packages given as arguments that are missing (apt-get, as root or with
# sudo). Sourced by scripts/setup.sh and bench/run.sh: `install_packages LABEL PACKAGE...`.

install_packages() {
  local label=$1
  shift
  local missing=() p sudo
  for p in "$@"; do
    dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
  done
  [ ${#missing[@]} -gt 0 ] || return 0
  echo "$label: installing ${missing[*]}" >&2
  if [ "$(id -u)" -eq 0 ]; then sudo=""; elif command -v sudo >/dev/null; then sudo="sudo"; else
    echo "$label: please install as root: apt-get install ${missing[*]}" >&2
    exit 1
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
}

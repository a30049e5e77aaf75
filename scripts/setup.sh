#!/usr/bin/env bash
# Installs the Debian packages voroseal needs that are not yet on this machine.
# Idempotent, non-interactive; run as root (or with sudo available).
set -euo pipefail

required=(
  build-essential cmake pkg-config
  libopenmesh-dev libeigen3-dev libtet1.5-dev
  libgtest-dev libbenchmark-dev
  libnanoflann-dev liblbfgspp-dev nlohmann-json3-dev libcli11-dev libtbb-dev
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  pybind11-dev python3-dev python3-numpy zlib1g-dev
)
# snakemake: runs studies as workflows (docs/studies.md); its test is skipped without it.
optional=(libceres-dev snakemake gmsh python3-meshio)  # gmsh, meshio: .msh files for io tests
# --bench: what bench/ needs besides (matplotlib draws bench/scale.py's plot).
if [ "${1:-}" = "--bench" ]; then optional+=(python3-matplotlib); fi

missing=()
for p in "${required[@]}" "${optional[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all packages present"
  exit 0
fi

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# Required packages must install; the optional ones may fail without stopping the build.
req_missing=()
for p in "${missing[@]}"; do
  case " ${optional[*]} " in *" $p "*) ;; *) req_missing+=("$p");; esac
done
if [ ${#req_missing[@]} -gt 0 ]; then
  $SUDO apt-get install -y -qq --no-install-recommends "${req_missing[@]}" >/dev/null
fi
for p in "${optional[@]}"; do
  case " ${missing[*]} " in
    *" $p "*) $SUDO apt-get install -y -qq --no-install-recommends "$p" >/dev/null \
                || echo "setup: optional $p not installed (continuing without it)";;
  esac
done
echo "setup: done"

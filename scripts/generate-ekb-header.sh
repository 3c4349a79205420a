#!/usr/bin/env bash
# Writes crates/ekb-capi/include/ekb.h anew from the C ABI's source (cbindgen, through the
# test that checks the committed header).
set -euo pipefail
cd "$(dirname "$0")/.."
EKB_BLESS=1 cargo test -p ekb-capi --test header

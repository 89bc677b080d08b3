#!/usr/bin/env bash
# CLI fuzzer: 2000 random argument lists (see cli_fuzz.py).
PYTHONPATH="$(cd "$(dirname "$0")" && pwd)${PYTHONPATH:+:$PYTHONPATH}" exec python3 "$(dirname "$0")/cli_fuzz.py" 2000

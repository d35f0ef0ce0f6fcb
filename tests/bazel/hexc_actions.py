#!/usr/bin/env python3
"""The hexc actions in a Bazel execution log (--execution_log_json_file: one JSON object per action that was not in
the local action cache), by target name, sorted, on one line:
    hexc_actions.py LOG ran       those hexc ran
    hexc_actions.py LOG cached    those the remote cache served"""
import json
import sys

log, which = sys.argv[1], sys.argv[2]
text, at, decoder, names = open(log).read(), 0, json.JSONDecoder(), []
while True:
    while at < len(text) and text[at].isspace():
        at += 1
    if at == len(text):
        break
    spawn, at = decoder.raw_decode(text, at)
    if spawn.get("mnemonic") == "HexcMaterial" and spawn.get("remoteCacheHit", False) == (which == "cached"):
        names.append(spawn["progressMessage"].removeprefix("hexc: compiling "))
print(" ".join(sorted(names)))

#!/usr/bin/python3
"""Writes CHECKPOINT.fnv for a checkpoint a test has changed on purpose, as
fe2dem writes it (FNV-1a 64 of the bytes and their count, file_hash.cpp), so
that --resume takes the changed file for an intact one.
Usage: refingerprint.py CHECKPOINT..."""
import sys

for path in sys.argv[1:]:
    data = open(path, "rb").read()
    h = 14695981039346656037
    for b in data:
        h = ((h ^ b) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    open(path + ".fnv", "w").write(f"{h:016x} {len(data)}\n")

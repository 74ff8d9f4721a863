#!/usr/bin/python3
"""The layers' include rule, read from the compiler's own dependency files.

Every object of a target (the *.o.d files CMake's Makefile generator keeps
beside the objects, in folders as the sources) lists each header its source reached. Fails if any of
them lies under a forbidden directory, naming the source, the header and
the chain's start; fails too if there are no dependency files to read.
Usage: check_layer_includes.py OBJECT_DIR FORBIDDEN_DIR...
"""
import glob
import os
import sys


def main(object_dir, forbidden):
    forbidden = [os.path.realpath(d).rstrip("/") + "/" for d in forbidden]
    depfiles = sorted(glob.glob(os.path.join(object_dir, "**", "*.o.d"), recursive=True))
    if not depfiles:
        print(f"FAIL no dependency files (*.o.d) in {object_dir}: build the target first")
        return 1
    bad = 0
    for d in depfiles:
        text = open(d).read().replace("\\\n", " ")
        headers = text.split(":", 1)[1].split() if ":" in text else []
        for h in headers:
            real = os.path.realpath(h)
            for f in forbidden:
                if real.startswith(f):
                    print(f"FAIL {os.path.basename(d)[:-4]} reaches {real} (under {f})")
                    bad += 1
    print(f"{len(depfiles)} objects checked, {bad} forbidden headers reached")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2:]))

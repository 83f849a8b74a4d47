#!/usr/bin/env python3
"""Frame lines as a render's journal holds them, for tests of long journals.

usage: journal_frames.py JOURNAL FROM TO
Prints frames FROM to TO-1, each a copy of JOURNAL's first frame line with the
frame's number and a cost of 1 + frame % 7 core-seconds, each line with its
check (FNV-1a 64 of its content, as pipeline/store/checked_line.hpp); with FROM
0 the journal's header line first, so the output is a whole journal.
"""
import re
import sys


def checked(content):
    h = 0xCBF29CE484222325
    for b in content:
        h = ((h ^ b) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return b"%s #%016x\n" % (content, h)


def main():
    journal, first, end = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    lines = open(journal, "rb").read().split(b"\n")
    frame = next(l.rpartition(b" #")[0] for l in lines if l.startswith(b"frame="))
    out = [lines[0] + b"\n"] if first == 0 else []
    for f in range(first, end):
        line = re.sub(rb"^frame=0 ", b"frame=%d " % f, frame)
        out.append(checked(re.sub(rb"core_seconds=[0-9.]+", b"core_seconds=%d" % (1 + f % 7), line)))
    sys.stdout.buffer.write(b"".join(out))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The mean FLIP over the scenes of each pattern of an `aapat study --compare
--json` document (a file, or - for standard input), a line "NAME MEAN" per
pattern in the document's order: the one reading of that document that
scripts/make-catalog.sh and scripts/catalog-validation.sh share."""
import json
import sys

doc = json.load(sys.stdin if sys.argv[1] == "-" else open(sys.argv[1]))
flip = doc["measures"].index("flip")
for p in doc["patterns"]:
    print(p["pattern"], repr(sum(s[flip] for s in p["measures"]) / len(p["measures"])))

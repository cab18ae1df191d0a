"""Validate OpenSCENARIO files against the ASAM schema of the version each declares.

Usage: validate_xosc.py SPEC_DIR FILE...   (SPEC_DIR holds OpenSCENARIOv1.0.xsd ... v1.3.xsd)
Prints one JSON object: {file: [error, ...]} (an empty list: valid).
"""
import json
import sys

from lxml import etree

SCHEMAS = {0: "OpenSCENARIOv1.0.xsd", 1: "OpenSCENARIOv1.1.1.xsd", 2: "OpenSCENARIOv1.2.xsd", 3: "OpenSCENARIOv1.3.xsd"}


def main():
    spec, files = sys.argv[1], sys.argv[2:]
    loaded = {}
    out = {}
    for f in files:
        try:
            doc = etree.parse(f)
            minor = int(doc.getroot().find("FileHeader").get("revMinor"))
            if minor not in loaded:
                loaded[minor] = etree.XMLSchema(etree.parse(f"{spec}/{SCHEMAS[minor]}"))
            schema = loaded[minor]
            schema.validate(doc)
            out[f] = [f"{e.line}:{e.column}: {e.message}" for e in schema.error_log]
        except Exception as e:  # a file that does not parse is an error too
            out[f] = [f"{type(e).__name__}: {e}"]
    json.dump(out, sys.stdout)


main()

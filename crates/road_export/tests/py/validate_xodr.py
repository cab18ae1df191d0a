"""Validates OpenDRIVE files against the OpenDRIVE 1.8 schema (XSD 1.1: xmlschema's
XMLSchema11, since the 1.8 schema uses xs:alternative and xs:assert, which libxml2 cannot read).

    python validate_xodr.py SCHEMA_DIR FILE.xodr...

Prints one JSON line per file: {"file", "valid", "errors": [first few messages]}.
"""

import json
import sys
from pathlib import Path

import xmlschema


def main() -> None:
    schema_dir = Path(sys.argv[1])
    schema = xmlschema.XMLSchema11(str(schema_dir / "OpenDRIVE_Core.xsd"))
    for f in sys.argv[2:]:
        errors = []
        try:
            for e in schema.iter_errors(f):
                errors.append(f"{e.path}: {e.reason}")
                if len(errors) >= 5:
                    break
        except Exception as e:  # noqa: BLE001 - unreadable is invalid
            errors.append(f"{type(e).__name__}: {e}")
        print(json.dumps({"file": f, "valid": not errors, "errors": errors}), flush=True)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Record the ASAM OpenSCENARIO API's expected checker messages as test data.

The API's C++ tests (cpp/applications/openScenarioTester/src/Test*V1_*.cpp in
RA-Consulting-GmbH/openscenario.api.test) say, per test file, which message a
reader must give, its severity and line:column. This script reads those sources
and writes one TSV row per (file, severity, line, column, message, test).
Run once by hand; its output is committed, so the tests never need the sources.

    tools/extract_checker_expectations.py SRC_DIR > crates/cli/tests/data/checker_suite_expectations.tsv
"""
import re
import sys
from pathlib import Path

FUNC = re.compile(r"bool\s+(\w+)::(\w+)\s*\(\s*\)\s*\{")
STRING = r'"((?:[^"\\]|\\.)*)"'
MSG = re.compile(
    r"FileContentMessage\(\s*((?:" + STRING + r"\s*)+),\s*NET_ASAM_OPENSCENARIO::(?:ErrorLevel::)?(\w+)\s*,\s*"
    r"NET_ASAM_OPENSCENARIO::Textmarker\(\s*(\d+)\s*,\s*(\d+)\s*,\s*(\w+)\s*\)\s*\)",
    re.S,
)
FILE_VAR = re.compile(r"(\w+)\s*=\s*_executablePath\s*\+\s*\"/\"\s*\+\s*kInputDir\s*\+\s*\"([^\"]+)\"")


def main(src_dir: str) -> None:
    rows = {}
    for cpp in sorted(Path(src_dir).glob("Test*V1_*.cpp")):
        text = cpp.read_text(encoding="utf-8", errors="replace")
        starts = [(m.start(), m.group(2)) for m in FUNC.finditer(text)]
        for i, (start, test) in enumerate(starts):
            end = starts[i + 1][0] if i + 1 < len(starts) else len(text)
            body = text[start:end]
            files = {m.group(1): m.group(2) for m in FILE_VAR.finditer(body)}
            for m in MSG.finditer(body):
                message = "".join(re.findall(STRING, m.group(1)))
                level, line, col, var = m.group(3), m.group(4), m.group(5), m.group(6)
                file = files.get(var)
                if file is None:
                    continue
                key = (file, level, int(line), int(col), message.replace("\t", " "))
                rows.setdefault(key, set()).add(f"{cpp.stem}::{test}")
    print("file\tseverity\tline\tcolumn\tmessage\ttests")
    for key in sorted(rows):
        print("\t".join(str(x) for x in key) + "\t" + ",".join(sorted(rows[key])))


if __name__ == "__main__":
    main(sys.argv[1])

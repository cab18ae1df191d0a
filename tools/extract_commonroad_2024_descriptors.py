#!/usr/bin/env python3
"""Extract the CommonRoad 2024 protobuf message definitions from a commonroad-io wheel.

commonroad-io (BSD-3-Clause) ships no .proto files, only the protoc-generated modules
`commonroad/common/protobuf/**/*_pb2.py`; each holds its file's serialized
FileDescriptorProto as a bytes literal (`serialized_pb=b'...'` in the 2026.1 wheel,
`AddSerializedFile(b'...')` in newer protoc output). This script reads those literals with
Python's own parser (nothing is imported or executed), orders the files so that every file
comes after the files it imports, and writes them as one FileDescriptorSet: the input
`prost-build` needs to generate Rust types, with no protoc.

    pip download commonroad-io==2026.1 --no-deps -d /tmp/crio
    tools/extract_commonroad_2024_descriptors.py /tmp/crio/commonroad_io-2026.1-py3-none-any.whl \
        crates/commonroad/proto/commonroad_2024.binpb

The wheel may also be given unpacked (the folder holding `commonroad/`). Only the standard
library is needed; the output is the same bytes for the same wheel.
"""
import ast
import sys
import zipfile
from pathlib import Path

PREFIX = "commonroad/common/protobuf/"


def pb2_sources(wheel: Path) -> dict:
    """{path inside the package: source text} of every *_pb2.py under PREFIX."""
    out = {}
    if wheel.is_dir():
        for p in sorted((wheel / PREFIX).rglob("*_pb2.py")):
            out[p.relative_to(wheel).as_posix()] = p.read_text(encoding="utf-8")
    else:
        with zipfile.ZipFile(wheel) as z:
            for name in sorted(z.namelist()):
                if name.startswith(PREFIX) and name.endswith("_pb2.py"):
                    out[name] = z.read(name).decode("utf-8")
    if not out:
        sys.exit(f"{wheel}: no {PREFIX}**/*_pb2.py inside")
    return out


def serialized_descriptor(path: str, source: str) -> bytes:
    """The bytes literal passed as `serialized_pb=` or to `AddSerializedFile(...)`."""
    found = []
    for node in ast.walk(ast.parse(source, filename=path)):
        if not isinstance(node, ast.Call):
            continue
        for kw in node.keywords:
            if kw.arg == "serialized_pb" and isinstance(kw.value, ast.Constant) and isinstance(kw.value.value, bytes):
                found.append(kw.value.value)
        func = node.func
        if isinstance(func, ast.Attribute) and func.attr == "AddSerializedFile" and node.args:
            arg = node.args[0]
            if isinstance(arg, ast.Constant) and isinstance(arg.value, bytes):
                found.append(arg.value)
    if len(found) != 1:
        sys.exit(f"{path}: expected one serialized FileDescriptorProto, found {len(found)}")
    return found[0]


def varint(data: bytes, i: int):
    shift = value = 0
    while True:
        b = data[i]
        i += 1
        value |= (b & 0x7F) << shift
        if b < 0x80:
            return value, i
        shift += 7


def name_and_imports(fdp: bytes):
    """FileDescriptorProto fields 1 (name) and 3 (dependency), read from the wire format."""
    name, deps, i = None, [], 0
    while i < len(fdp):
        key, i = varint(fdp, i)
        field, wire = key >> 3, key & 7
        if wire == 0:
            _, i = varint(fdp, i)
        elif wire == 1:
            i += 8
        elif wire == 5:
            i += 4
        elif wire == 2:
            n, i = varint(fdp, i)
            value = fdp[i:i + n]
            i += n
            if field == 1:
                name = value.decode("utf-8")
            elif field == 3:
                deps.append(value.decode("utf-8"))
        else:
            sys.exit(f"unexpected wire type {wire} in a FileDescriptorProto")
    return name, deps


def encode_varint(n: int) -> bytes:
    out = bytearray()
    while True:
        b = n & 0x7F
        n >>= 7
        out.append(b | (0x80 if n else 0))
        if not n:
            return bytes(out)


def main(wheel: str, out: str) -> None:
    files = {}
    for path, source in pb2_sources(Path(wheel)).items():
        fdp = serialized_descriptor(path, source)
        name, deps = name_and_imports(fdp)
        files[name] = (fdp, deps)
    # dependencies first; ties by name, so the order is fixed
    ordered, done = [], set()

    def visit(name, stack=()):
        if name in done:
            return
        if name in stack:
            sys.exit(f"import cycle through {name}")
        if name not in files:
            sys.exit(f"{stack[-1]} imports {name}, which the wheel does not hold")
        for dep in sorted(files[name][1]):
            visit(dep, stack + (name,))
        done.add(name)
        ordered.append(name)

    for name in sorted(files):
        visit(name)
    fds = bytearray()
    for name in ordered:
        fdp = files[name][0]
        fds += b"\x0a" + encode_varint(len(fdp)) + fdp  # FileDescriptorSet.file = 1
    Path(out).write_bytes(bytes(fds))
    print(f"{out}: {len(ordered)} files, {len(fds)} bytes", file=sys.stderr)
    for name in ordered:
        print(f"  {name}", file=sys.stderr)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])

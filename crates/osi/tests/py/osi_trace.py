"""Reading an OSI trace file: GroundTruth messages, each after its 4-byte little-endian length."""
import struct

from osi3.osi_groundtruth_pb2 import GroundTruth


def read(path):
    data = open(path, "rb").read()
    out, i = [], 0
    while i < len(data):
        (n,) = struct.unpack_from("<I", data, i)
        i += 4
        g = GroundTruth()
        g.ParseFromString(data[i:i + n])
        i += n
        out.append(g)
    return out

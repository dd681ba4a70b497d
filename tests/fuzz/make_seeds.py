"""Writes the hand-made seeds of the fuzz corpora (tests/fuzz/corpus-mesh, corpus-files): small
inputs in each format the targets decode, valid and broken, from which libFuzzer mutates.
The corpora also keep what libFuzzer found (files named by their SHA-1, merged with -merge=1).
Usage: python3 tests/fuzz/make_seeds.py   (from the repository root; rewrites the seeds only)
"""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

# --- fuzz_mesh.cxx: flags, [blocks], then per mesh: point count, coordinates (a byte < 16 is a
# special value: 0 NaN, 1 inf, 5 the smallest subnormal, 11 DBL_MAX; else the next byte b is
# (b - 128) / 16), cell count, per cell: kind | size << 2, ids (a byte < 5 is a bad id: 0 -> -1,
# 1 -> one past the end; else b % points).
SPECIAL = {"nan": 0, "inf": 1, "tiny": 5, "-FLT_MAX": 10, "huge": 11}


def coord(x):
    if isinstance(x, str):
        return bytes([SPECIAL[x]])
    return bytes([200, int(round(x * 16 + 128))])


def point_id(k, n):
    if k == "past":
        return bytes([1])
    if k == "neg":
        return bytes([0])
    v = k
    while v < 5:
        v += max(n, 1)
    return bytes([v])


def mesh(points, cells):
    b = bytes([len(points)])
    for p in points:
        for c in p:
            b += coord(c)
    b += bytes([len(cells)])
    for kind, ids in cells:
        b += bytes([kind | (len(ids) << 2)])
        for k in ids:
            b += point_id(k, len(points))
    return b


TET_P = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TET_C = [(2, [0, 2, 1]), (2, [0, 1, 3]), (2, [0, 3, 2]), (2, [1, 2, 3])]
CUBE_P = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
CUBE_C = [(2, [0, 2, 3, 1]), (2, [4, 5, 7, 6]), (2, [0, 1, 5, 4]), (2, [2, 6, 7, 3]),
          (2, [0, 4, 6, 2]), (2, [1, 3, 7, 5])]
SHEET_P = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
SHEET_C = [(2, [0, 1, 2]), (2, [0, 2, 3])]
MESH_SEEDS = {
    "tetrahedron": bytes([0]) + mesh(TET_P, TET_C),
    "cube_filters": bytes([64]) + mesh(CUBE_P, CUBE_C),
    "sheet": bytes([0]) + mesh(SHEET_P, SHEET_C),
    "sheet_solid": bytes([4]) + mesh(SHEET_P, SHEET_C),
    "bad_id": bytes([64]) + mesh(TET_P, TET_C[:3] + [(2, [1, 2, "past"])]),
    "negative_id": bytes([0]) + mesh(TET_P, TET_C[:3] + [(2, [1, "neg", 3])]),
    "nan_point": bytes([64]) + mesh(TET_P[:3] + [("nan", 0, 1)], TET_C),
    "huge_tiny": bytes([16 | 64]) + mesh([("huge", 0, 0), (0, "tiny", 0), (0, 0, 1), (1, 1, 1)],
                                         TET_C),
    "mixed_cells": bytes([32]) + mesh(TET_P, [(0, [0]), (1, [0, 1]), (3, [0, 1, 2, 3]),
                                              (2, [0, 2, 1])]) + bytes([200, 128]) * 12,
    "composite": bytes([1, 1]) + mesh(TET_P, TET_C) + mesh([], []),
    "across_ranks_open": bytes([2]) + mesh(SHEET_P + TET_P,
                                           SHEET_C + [(2, [4, 6, 5]), (2, [4, 5, 7])]),
    "empty": bytes([0]) + mesh([], []),
    # Findings, each fixed (docs/stability.md): strips of no point crashed vtkPolyDataNormals
    # in the reference filters; DBL_MAX made the surface model's volume infinite (now refused:
    # beyond float range); -FLT_MAX failed Embree's assertion in ISR's distances.
    "found_empty_strips": bytes([64]) + mesh(TET_P, [(3, []), (3, []), (2, [0, 2, 1])]),
    "found_beyond_float_range": bytes([16 | 64]) + mesh([("huge", -8, 0)] + TET_P[1:], TET_C),
    "found_float_max_embree": bytes([64]) + mesh(TET_P[:3] + [(-7.625, -7.5, "-FLT_MAX")],
                                                 TET_C),
}

# --- fuzz_files.cxx: byte 0 the kind (index below), byte 1 bit 0 contour at (byte 1 >> 1) / 8,
# then the file.
KINDS = [".vtp", ".vtu", ".vti", ".vts", ".vtr", ".vtk", ".stl", ".ply", ".obj", ".pvd",
         ".hdr", ".exr", ".png", ".jpg", ".tif"]
VTP = b"""<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">
<PolyData><Piece NumberOfPoints="4" NumberOfPolys="4">
<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">
0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>
<Polys><DataArray type="Int32" Name="connectivity" format="ascii">0 2 1 0 1 3 0 3 2 1 2 3</DataArray>
<DataArray type="Int32" Name="offsets" format="ascii">3 6 9 12</DataArray></Polys>
</Piece></PolyData></VTKFile>
"""
VTI = b"""<?xml version="1.0"?>
<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">
<ImageData WholeExtent="0 2 0 2 0 2" Origin="0 0 0" Spacing="1 1 1">
<Piece Extent="0 2 0 2 0 2"><PointData Scalars="s">
<DataArray type="Float32" Name="s" format="ascii">
0 0 0 0 0 0 0 0 0  0 0 0 0 8 0 0 0 0  0 0 0 0 0 0 0 0 0</DataArray>
</PointData></Piece></ImageData></VTKFile>
"""
VTK_LEGACY = b"""# vtk DataFile Version 3.0
tetrahedron
ASCII
DATASET POLYDATA
POINTS 4 float
0 0 0 1 0 0 0 1 0 0 0 1
POLYGONS 4 16
3 0 2 1
3 0 1 3
3 0 3 2
3 1 2 3
"""
VTK_BAD_ID = VTK_LEGACY.replace(b"3 1 2 3\n", b"3 1 2 9\n")
VTK_HUGE_COUNT = VTK_LEGACY.replace(b"POINTS 4 float", b"POINTS 400000000 float")
STL = b"""solid t
facet normal 0 0 -1
outer loop
vertex 0 0 0
vertex 0 1 0
vertex 1 0 0
endloop
endfacet
endsolid t
"""
PLY = b"""ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
element face 4
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
0 1 0
0 0 1
3 0 2 1
3 0 1 3
3 0 3 2
3 1 2 3
"""
PLY_BAD_ID = PLY.replace(b"3 1 2 3\n", b"3 1 2 7\n")
OBJ = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
OBJ_BAD_ID = OBJ.replace(b"f 2 3 4\n", b"f 2 3 9\n")
PVD = b"""<?xml version="1.0"?>
<VTKFile type="Collection" version="0.1">
<Collection><DataSet timestep="0" file="missing_0.vtp"/><DataSet timestep="1" file="input.vtp"/>
</Collection></VTKFile>
"""
HDR = (b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n" +
       bytes([128, 64, 32, 129] * 8))
# A 2x1 RGB PNG (zlib-stored), made by hand so that no image library is needed.


def png():
    import zlib

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
    raw = b"\x00" + bytes([255, 0, 0, 0, 0, 255])
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 1, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def file_seed(extension, content, contour=None):
    flags = 0 if contour is None else 1 | (int(contour * 8) << 1)
    return bytes([KINDS.index(extension), flags]) + content


FILE_SEEDS = {
    "vtp": file_seed(".vtp", VTP),
    "vti_contour": file_seed(".vti", VTI, contour=4.0),
    "vti_surface": file_seed(".vti", VTI),
    "vtk": file_seed(".vtk", VTK_LEGACY),
    "vtk_bad_id": file_seed(".vtk", VTK_BAD_ID),
    "vtk_huge_count": file_seed(".vtk", VTK_HUGE_COUNT),
    "stl": file_seed(".stl", STL),
    "ply": file_seed(".ply", PLY),
    "ply_bad_id": file_seed(".ply", PLY_BAD_ID),
    "obj": file_seed(".obj", OBJ),
    "obj_bad_id": file_seed(".obj", OBJ_BAD_ID),
    "pvd": file_seed(".pvd", PVD),
    "hdr": file_seed(".hdr", HDR),
    "png": file_seed(".png", png()),
    "empty_vtp": file_seed(".vtp", b""),
}
# Findings of fuzz_files, kept in corpus-files under their own names (not written here):
# ply_property_before_element (crashed vtkPLYReader), stl_binary_count_beyond_file (a binary
# STL's count had vtkSTLReader allocate 19 GB), vtk_points_beyond_data (a legacy file with
# fewer points than it declares crashed vtkDataSetReader: now read in a child first),
# ply_body_beyond_buffer (vtkPLYReader overran a buffer, which AddressSanitizer caught in
# the child); vtk_empty_polygon and ply_empty_face (a polygon of no points: vtkPolyDataNormals
# read through a null pointer, found by CI's bounded run), with vtk_short_tetra,
# vtk_offsets_beyond_connectivity and vtk_unknown_cell_type, the other cells VTK's filters
# cannot read (the viewer now checks cells against their types and offsets);
# vtk_keyword_prefix_count ("POINTS4 400000000": VTK's legacy reader matches keywords by
# their first letters, the declared-size check now does too).

if __name__ == "__main__":
    for folder, seeds in (("corpus-mesh", MESH_SEEDS), ("corpus-files", FILE_SEEDS)):
        os.makedirs(os.path.join(HERE, folder), exist_ok=True)
        for name, data in seeds.items():
            with open(os.path.join(HERE, folder, "seed_" + name), "wb") as f:
                f.write(data)
        print("%s: %d seeds" % (folder, len(seeds)))

#!/usr/bin/env python3
"""The HDF5 snapshots of a run directory as ParaView's XDMF reader sees them, checked with h5py and
a strict XML parse (no ParaView needed): every .xdmf is well-formed XDMF 3 with a temporal
collection; each DataItem names a dataset of its .h5 file with the shape and type it declares;
triangles index existing points. With a second run directory written as VTK (output.format=vtk,
the same run), every array of each .vti/.vtp snapshot is in the HDF5 one and equal bit for bit,
as are the points, triangles, origin and spacing.

Usage: check_hdf5_output.py HDF5_RUN_DIRECTORY [VTK_RUN_DIRECTORY]
Exit 0 when all holds, 1 with one line per problem otherwise."""
import base64
import os
import struct
import sys
import xml.etree.ElementTree as ElementTree

import h5py
import numpy

problems = []

NUMBER_TYPES = {("Float", "8"): numpy.dtype("<f8"), ("Int", "4"): numpy.dtype("<i4"),
                ("UChar", "1"): numpy.dtype("u1")}


def problem(text):
    problems.append(text)


def read_item(directory, item, where):
    """The dataset a Format="HDF" DataItem names, checked against its Dimensions and type."""
    file_name, _, dataset = item.text.strip().partition(":")
    path = os.path.join(directory, file_name)
    with h5py.File(path, "r") as h5:
        if dataset not in h5:
            problem(f"{where}: {dataset} is not in {file_name}")
            return None
        values = h5[dataset][()]
    shape = tuple(int(n) for n in item.get("Dimensions").split())
    if values.shape != shape:
        problem(f"{where}: {file_name}:{dataset} has shape {values.shape}, the XDMF says {shape}")
    expected = NUMBER_TYPES.get((item.get("NumberType"), item.get("Precision")))
    if expected is None or values.dtype != expected:
        problem(f"{where}: {file_name}:{dataset} is {values.dtype}, the XDMF says "
                f"{item.get('NumberType')} {item.get('Precision')}")
    return values


def read_vtk_arrays(path):
    """Points, triangles and point arrays of a .vti/.vtp written with base64 (UInt64 header)."""
    root = ElementTree.parse(path).getroot()
    arrays = {}
    for element in root.iter("DataArray"):
        raw = base64.b64decode(element.text.strip())
        (count,) = struct.unpack("<Q", raw[:8])
        dtype = {"Float64": "<f8", "Int32": "<i4", "Int64": "<i8", "UInt8": "u1"}[element.get("type")]
        values = numpy.frombuffer(raw[8:8 + count], dtype=dtype)
        components = int(element.get("NumberOfComponents", "1"))
        arrays[element.get("Name")] = values.reshape(-1, components) if components > 1 else values
    return root, arrays


def compare(name, h5_values, vtk_values, where):
    if vtk_values is None:
        problem(f"{where}: {name} is not in the VTK file")
    elif h5_values.size != vtk_values.size or not numpy.array_equal(
            h5_values.reshape(-1), vtk_values.reshape(-1).astype(h5_values.dtype)):
        problem(f"{where}: {name} differs from the VTK file's")


def vtk_file_of(vtk_directory, h5_file):
    """vtk/<kind>_<step>.vti|vtp for h5/<kind>_<step>.h5 (a single cell: cell0)."""
    stem = os.path.basename(h5_file)[:-len(".h5")]
    kind, _, step = stem.partition("_")
    if kind == "fluid":
        return os.path.join(vtk_directory, "vtk", f"fluid_{step}.vti")
    together = os.path.join(vtk_directory, "vtk", f"cells_{step}.vtp")
    return together if os.path.exists(together) else os.path.join(vtk_directory, "vtk",
                                                                   f"cell0_{step}.vtp")


def check_grid(directory, grid, vtk_directory, where):
    topology = grid.find("Topology")
    geometry = grid.find("Geometry")
    data = {}
    h5_file = None
    if topology.get("TopologyType") == "Triangle":
        triangles = read_item(directory, topology.find("DataItem"), where)
        points = read_item(directory, geometry.find("DataItem"), where)
        h5_file = topology.find("DataItem").text.strip().partition(":")[0]
        if triangles is not None and points is not None:
            if triangles.min() < 0 or triangles.max() >= len(points):
                problem(f"{where}: triangles index points outside 0..{len(points) - 1}")
            if int(topology.get("NumberOfElements")) != len(triangles):
                problem(f"{where}: NumberOfElements is not the triangle count")
    elif topology.get("TopologyType") == "3DCoRectMesh":
        if geometry.get("GeometryType") != "ORIGIN_DXDYDZ":
            problem(f"{where}: an image without ORIGIN_DXDYDZ geometry")
        points = triangles = None
    else:
        problem(f"{where}: unexpected topology {topology.get('TopologyType')}")
        return
    for attribute in grid.findall("Attribute"):
        item = attribute.find("DataItem")
        h5_file = item.text.strip().partition(":")[0]
        data[attribute.get("Name")] = read_item(directory, item, f"{where} {attribute.get('Name')}")
    if vtk_directory is None or h5_file is None:
        return
    vtk_path = vtk_file_of(vtk_directory, h5_file)
    if not os.path.exists(vtk_path):
        problem(f"{where}: no VTK snapshot {vtk_path} to compare with")
        return
    root, vtk = read_vtk_arrays(vtk_path)
    for name, values in vtk.items():
        if name in ("Points", "connectivity", "offsets"):
            continue
        if data.get(name) is None:
            problem(f"{where}: {name} of {vtk_path} is not in the HDF5 snapshot")
        else:
            compare(name, data[name], values, f"{where} vs {vtk_path}")
    if points is not None:
        compare("points", points, vtk.get("Points"), f"{where} vs {vtk_path}")
        compare("triangles", triangles, vtk.get("connectivity"), f"{where} vs {vtk_path}")
    else:
        image = root.find("ImageData")
        spacing = [float(v) for v in geometry.findall("DataItem")[1].text.split()]
        origin = [float(v) for v in geometry.findall("DataItem")[0].text.split()]
        if origin[::-1] != [float(v) for v in image.get("Origin").split()] or \
                spacing[::-1] != [float(v) for v in image.get("Spacing").split()]:
            problem(f"{where}: origin or spacing differ from {vtk_path}")


def check_series(directory, name, vtk_directory):
    path = os.path.join(directory, name)
    root = ElementTree.parse(path).getroot()  # raises on malformed XML
    if root.tag != "Xdmf" or root.get("Version") != "3.0":
        problem(f"{path}: not XDMF 3.0")
        return 0
    collection = root.find("Domain/Grid")
    if collection is None or collection.get("CollectionType") != "Temporal":
        problem(f"{path}: no temporal collection")
        return 0
    times = []
    for grid in collection.findall("Grid"):
        times.append(float(grid.find("Time").get("Value")))
        check_grid(directory, grid, vtk_directory, f"{name} t={times[-1]}")
    if not times or times != sorted(set(times)):
        problem(f"{path}: times {times} not ascending")
    return len(times)


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__)
        return 2
    directory = sys.argv[1]
    vtk_directory = sys.argv[2] if len(sys.argv) == 3 else None
    series = [name for name in ("cells.xdmf", "fluid.xdmf")
              if os.path.exists(os.path.join(directory, name))]
    if not series:
        problem(f"{directory}: no .xdmf series")
    counts = {name: check_series(directory, name, vtk_directory) for name in series}
    for line in problems:
        print(line)
    if not problems:
        compared = f", equal to {vtk_directory}'s VTK" if vtk_directory else ""
        print(f"{directory}: {counts} snapshots well-formed{compared}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

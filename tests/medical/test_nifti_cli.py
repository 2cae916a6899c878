"""NIfTI scans given to the isoform command, made here with nibabel from the
real scans in ../shared/data: world coordinates against nibabel's own
affine, the same contour from NIfTI, NRRD and the converted .vdb, 4-D files,
scaled CT values, and damaged files.

Run by CTest through pytest; ISOFORM_CLI names the isoform program and
ISOFORM_SHARED_DATA the real-data folder.
"""
import gzip
import json
import math
import os
import struct
import subprocess

import nibabel
import numpy as np
import pytest

CLI = os.environ["ISOFORM_CLI"]
DATA = os.environ["ISOFORM_SHARED_DATA"]


def isoform(*args, expect=0):
    proc = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=300)
    assert proc.returncode == expect, f"isoform {' '.join(map(str, args))}: exit {proc.returncode}\n{proc.stderr}"
    return proc


def info(path, *extra):
    return json.loads(isoform(*extra, "info", path, "--json").stdout)["grids"][0]


def headsq():
    """The CT head as an array indexed [x, y, z] (NIfTI's order)."""
    raw = np.fromfile(os.path.join(DATA, "headsq_64x64x93_u16le.raw"), dtype="<u2")
    return raw.reshape(93, 64, 64).transpose(2, 1, 0)


def oblique_affine():
    """Voxel sizes 3.2, 3.2, 1.5 turned 30 degrees about z and 10 about x, then moved."""
    a, b = math.radians(30), math.radians(10)
    rz = np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]])
    rx = np.array([[1, 0, 0], [0, math.cos(b), -math.sin(b)], [0, math.sin(b), math.cos(b)]])
    affine = np.eye(4)
    affine[:3, :3] = rz @ rx @ np.diag([3.2, 3.2, 1.5])
    affine[:3, 3] = [-101.5, 20.25, 7.0]
    return affine


def transform(grid):
    return np.array(grid["transform"])


@pytest.mark.parametrize("form", ["sform", "qform"])
@pytest.mark.parametrize("suffix", [".nii", ".nii.gz"])
def test_world_map_is_nibabels(tmp_path, form, suffix):
    image = nibabel.Nifti1Image(headsq().astype(np.int16), None)
    if form == "sform":
        image.set_sform(oblique_affine(), code=1)
        image.set_qform(None, code=0)
    else:
        image.set_qform(oblique_affine(), code=1)
        image.set_sform(None, code=0)
    image.header.set_xyzt_units("mm")
    path = tmp_path / f"head{suffix}"
    nibabel.save(image, path)
    expected = nibabel.load(path).affine  # nibabel's reading of what it wrote
    grid = info(path)
    assert np.allclose(transform(grid), expected, atol=1e-4), (transform(grid), expected)
    assert grid["space"] == "RAS" and grid["unit"] == "mm"
    assert grid["bbox_max"] == [63, 63, 92]
    assert grid["value_max"] == 3926


def test_nifti2_and_no_orientation(tmp_path):
    image = nibabel.Nifti2Image(headsq().astype(np.uint16), oblique_affine())
    nibabel.save(image, tmp_path / "head2.nii")
    assert np.allclose(transform(info(tmp_path / "head2.nii")), oblique_affine(), atol=1e-9)
    bare = nibabel.Nifti1Image(headsq().astype(np.uint16), None)
    bare.header.set_zooms((3.2, 3.2, 1.5))
    nibabel.save(bare, tmp_path / "bare.nii")
    # Neither form: both codes 0 in the file (nibabel writes a qform of its own).
    data = bytearray((tmp_path / "bare.nii").read_bytes())
    struct.pack_into("<hh", data, 252, 0, 0)
    (tmp_path / "bare.nii").write_bytes(bytes(data))
    assert nibabel.load(tmp_path / "bare.nii").header.get_sform(coded=True)[1] == 0
    grid = info(tmp_path / "bare.nii")
    assert np.allclose(transform(grid), np.diag([3.2, 3.2, 1.5, 1.0]), atol=1e-6)
    assert grid["space"] is None


def contour_summary(path, out, *extra):
    return json.loads(isoform("contour", path, "--iso", "1150.5", "-o", out, "--json", *extra).stdout)


def test_one_scan_one_contour_from_every_format(tmp_path):
    """The head as NIfTI, as NRRD with the same map, and the NIfTI converted to
    .vdb: the same contour, at the same world coordinates, closed where the
    scan does not end."""
    volume = headsq()
    affine = oblique_affine()
    image = nibabel.Nifti1Image(volume.astype(np.uint16), affine)
    image.header.set_xyzt_units("mm")
    nibabel.save(image, tmp_path / "head.nii.gz")
    directions = " ".join("(" + ",".join(repr(float(v)) for v in affine[:3, a]) + ")" for a in range(3))
    header = ("NRRD0005\ntype: uint16\ndimension: 3\nspace: right-anterior-superior\nsizes: 64 64 93\n"
              f"space directions: {directions}\nspace origin: ({','.join(repr(float(v)) for v in affine[:3, 3])})\n"
              "space units: \"mm\" \"mm\" \"mm\"\nendian: little\nencoding: gzip\n\n")
    with open(tmp_path / "head.nrrd", "wb") as f:
        f.write(header.encode() + gzip.compress(volume.transpose(2, 1, 0).astype("<u2").tobytes()))
    isoform("convert", tmp_path / "head.nii.gz", "-o", tmp_path / "head.vdb")
    summaries = {name: contour_summary(tmp_path / name, tmp_path / (name + ".ply"))
                 for name in ["head.nii.gz", "head.nrrd", "head.vdb"]}
    first, nrrd, vdb = summaries["head.nii.gz"], summaries["head.nrrd"], summaries["head.vdb"]
    assert first["triangles"] > 50000
    for name in summaries:  # the .vdb keeps the NIfTI's frame and unit
        assert (summaries[name]["space"], summaries[name]["unit"]) == ("RAS", "mm"), name
    # The two dense readers give the same mesh.
    for key in ["vertices", "triangles", "parts", "euler_characteristic", "boundary_edges", "bbox_min", "bbox_max"]:
        assert np.allclose(nrrd[key], first[key], atol=1e-4), (key, nrrd[key], first[key])
    # The sparse .vdb closes the bone where the scan ends (the dense contour
    # stops there): closed, and within a voxel of the same place.
    assert first["boundary_edges"] > 0 and vdb["boundary_edges"] == 0 and vdb["nonmanifold_edges"] == 0
    assert np.allclose(vdb["bbox_min"], first["bbox_min"], atol=3.3), (vdb["bbox_min"], first["bbox_min"])
    assert np.allclose(vdb["bbox_max"], first["bbox_max"], atol=3.3), (vdb["bbox_max"], first["bbox_max"])
    # The bounding box is the hand-computed image of the contour's index box.
    grid = info(tmp_path / "head.nii.gz")
    assert np.allclose(transform(grid), affine, atol=1e-5)


def test_four_dimensions_need_a_volume(tmp_path):
    series = np.stack([headsq(), headsq() // 2], axis=-1).astype(np.int16)
    path = tmp_path / "series.nii.gz"
    nibabel.save(nibabel.Nifti1Image(series, oblique_affine()), path)
    err = isoform("info", path, expect=1).stderr.strip()
    assert err == (f"isoform: error: {path}: a 4-D NIfTI of 2 volumes (64x64x93x2); choose one with --volume K "
                   "(the open options' volume), K from 0 to 1"), err
    assert info(path, "--volume", "0")["value_max"] == 3926
    assert json.loads(isoform("info", path, "--json", "--volume", "1").stdout)["grids"][0]["value_max"] == 1963
    err = isoform("--volume", "2", "info", path, expect=1).stderr
    assert "volume 2 asked of a NIfTI with 2 volumes" in err


def test_ct_values_are_rescaled(tmp_path):
    image = nibabel.Nifti1Image(headsq().astype(np.int16), oblique_affine())
    image.header.set_slope_inter(2.0, -1024.0)
    path = tmp_path / "hu.nii"
    nibabel.save(image, path)
    grid = info(path)
    assert (grid["value_min"], grid["value_max"]) == (-1024.0, 2 * 3926 - 1024.0)


def damaged_files(tmp_path):
    image = nibabel.Nifti1Image(headsq().astype(np.int16), oblique_affine())
    good = tmp_path / "good.nii"
    nibabel.save(image, good)
    data = good.read_bytes()
    cases = {}

    def variant(name, at, fmt, value):
        patched = bytearray(data)
        struct.pack_into(fmt, patched, at, value)
        cases[name] = bytes(patched)

    variant("zero_pixdim.nii", 80, "<f", 0.0)
    variant("nan_pixdim.nii", 84, "<f", float("nan"))
    variant("far_vox_offset.nii", 108, "<f", 1e9)
    variant("huge_dims.nii", 42, "<h", 30000)
    cases["truncated.nii.gz"] = gzip.compress(data)[: len(gzip.compress(data)) // 2]
    cases["cut.nii"] = data[: len(data) - 1000]
    for name, content in cases.items():
        (tmp_path / name).write_bytes(content)
    return cases


@pytest.mark.parametrize("name,says", [
    ("zero_pixdim.nii", "pixdim[1], a voxel size, is 0"),
    ("nan_pixdim.nii", "pixdim[2], a voxel size, is NaN"),
    ("far_vox_offset.nii", "need bytes up to 1000"),
    ("huge_dims.nii", "need bytes up to"),
    ("truncated.nii.gz", "its gzip data end"),
    ("cut.nii", "need bytes up to"),
])
def test_damaged_files_are_named_and_nothing_is_written(tmp_path, name, says):
    damaged_files(tmp_path)
    path = tmp_path / name
    before = sorted(os.listdir(tmp_path))
    for args in (["info", path], ["contour", path, "--iso", "500", "-o", tmp_path / "out.ply"],
                 ["convert", path, "-o", tmp_path / "out.vdb"]):
        err = isoform(*args, expect=1).stderr.strip().split("\n")
        assert len(err) == 1 and err[0].startswith(f"isoform: error: {path}: "), err
        assert says in err[0], err[0]
    assert sorted(os.listdir(tmp_path)) == before


def ply_parts(path):
    """The part id of every triangle of a binary PLY that isoform wrote."""
    data = path.read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().split("\n")
    vertices = int(next(line.split()[2] for line in header if line.startswith("element vertex")))
    faces = int(next(line.split()[2] for line in header if line.startswith("element face")))
    face_at = header.index(next(line for line in header if line.startswith("element face")))
    vertex_bytes = 4 * len([line for line in header[:face_at] if line.startswith("property float")])
    assert header[face_at + 1:face_at + 3] == ["property list uchar int vertex_indices", "property int part"], header
    face = np.dtype([("n", "u1"), ("v", "<i4", 3), ("part", "<i4")])
    triangles = np.frombuffer(data, dtype=face, count=faces, offset=end + vertices * vertex_bytes)
    assert (triangles["n"] == 3).all()
    return triangles["part"]


def test_specks_are_dropped_from_the_frog(tmp_path):
    """The frog CT at 20.5 has about 1,160 parts, most of a few triangles."""
    frog = tmp_path / "frog.vdb"
    isoform("convert", os.path.join(DATA, "frog_256x256x44_u16le.raw"), "--dims", "256,256,44", "--type", "u16",
            "-o", frog)
    whole = json.loads(isoform("contour", frog, "--iso", "20.5", "-o", tmp_path / "all.ply", "--json").stdout)
    kept = json.loads(isoform("contour", frog, "--iso", "20.5", "--min-part", "50", "-o", tmp_path / "kept.ply",
                              "--json").stdout)
    assert whole["parts"] > 1000
    assert kept["parts"] == whole["parts"] - kept["parts_dropped"] and kept["parts_dropped"] > 500
    assert kept["triangles"] == whole["triangles"] - kept["triangles_dropped"]
    assert kept["boundary_edges"] == whole["boundary_edges"] == 0 and kept["nonmanifold_edges"] == 0
    sizes = np.bincount(ply_parts(tmp_path / "kept.ply"))
    assert len(sizes) == kept["parts"] and sizes.min() >= 50
    # Each part of the whole contour of 50 triangles or more is kept, and no other.
    whole_sizes = np.bincount(ply_parts(tmp_path / "all.ply"))
    assert sorted(sizes) == sorted(whole_sizes[whole_sizes >= 50])
    largest = json.loads(isoform("contour", frog, "--iso", "20.5", "--largest", "3", "-o", tmp_path / "three.ply",
                                 "--json").stdout)
    assert largest["parts"] == 3
    assert largest["triangles"] == sum(sorted(whole_sizes)[-3:])
    # A volume needs a unit the .vdb of a raw scan does not state.
    err = isoform("contour", frog, "--iso", "20.5", "--min-part", "1mm3", "-o", tmp_path / "v.ply", expect=2).stderr
    assert "does not state its unit" in err and not (tmp_path / "v.ply").exists()
    # The reduction drops the specks of its input first.
    reduced = json.loads(isoform("reduce", tmp_path / "all.ply", "--min-part", "50", "--keep", "50%",
                                 "-o", tmp_path / "r.ply", "--json").stdout)
    assert reduced["parts"] == kept["parts"] and reduced["parts_dropped"] == kept["parts_dropped"]


def test_specks_by_volume_in_millimetres(tmp_path):
    image = nibabel.Nifti1Image(headsq().astype(np.int16), oblique_affine())
    image.header.set_xyzt_units("mm")
    nibabel.save(image, tmp_path / "head.nii.gz")
    ml = json.loads(isoform("contour", tmp_path / "head.nii.gz", "--iso", "1150.5", "--min-part", "0.5ml",
                            "-o", tmp_path / "a.ply", "--json").stdout)
    mm3 = json.loads(isoform("contour", tmp_path / "head.nii.gz", "--iso", "1150.5", "--min-part", "500mm3",
                             "-o", tmp_path / "b.ply", "--json").stdout)
    assert ml["parts_dropped"] > 0 and ml["triangles"] == mm3["triangles"]
    err = isoform("contour", tmp_path / "head.nii.gz", "--min-part", "lots", "-o", tmp_path / "c.ply", expect=2).stderr
    assert "--min-part: 'lots' is not a triangle count" in err


def test_space_converts_between_patient_frames(tmp_path):
    image = nibabel.Nifti1Image(headsq().astype(np.int16), oblique_affine())
    image.header.set_xyzt_units("mm")
    nibabel.save(image, tmp_path / "head.nii")
    ras = contour_summary(tmp_path / "head.nii", tmp_path / "ras.ply")
    lps = contour_summary(tmp_path / "head.nii", tmp_path / "lps.ply", "--space", "lps")
    las = contour_summary(tmp_path / "head.nii", tmp_path / "las.ply", "--space", "LAS")
    assert (lps["space"], lps["space_converted_from"]) == ("LPS", "RAS")
    # RAS to LPS is a half turn about z: x and y change sign.
    assert np.allclose(lps["bbox_min"], [-ras["bbox_max"][0], -ras["bbox_max"][1], ras["bbox_min"][2]], atol=1e-4)
    assert np.allclose(las["bbox_max"], [-ras["bbox_min"][0], ras["bbox_max"][1], ras["bbox_max"][2]], atol=1e-4)
    for summary in (lps, las):  # a mirror (LAS) keeps the mesh consistently oriented
        for key in ["triangles", "parts", "boundary_edges", "nonmanifold_edges", "inconsistent_edges"]:
            assert summary[key] == ras[key], key
    isoform("convert", os.path.join(DATA, "headsq_64x64x93_u16le.raw"), "--dims", "64,64,93", "-o",
            tmp_path / "raw.vdb")
    err = isoform("contour", tmp_path / "raw.vdb", "--iso", "1150.5", "--space", "LPS", "-o", tmp_path / "x.ply",
                  expect=2).stderr
    assert "does not state its patient frame" in err and not (tmp_path / "x.ply").exists()

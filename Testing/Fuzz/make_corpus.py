#!/usr/bin/env python3
"""Writes the seed and regression inputs of the fuzz targets into Testing/Fuzz/corpus/.

Deterministic (no time stamps, no randomness) and standard library only: run it again
and `git diff` shows nothing. Seeds are small excerpts of real files: the CRESCENT CFM
TSurf files in ../shared/data/crescent-cfm (CC BY 4.0, see corpus/README.md; only the
first vertices and their triangles are copied), the Jacksboro DEM of Debian's
python-matplotlib-data (a 6 x 7 crop), the stylus traces in Data/. Those excerpts are
rewritten only when their source is present; the rest is always written.

Regression inputs (regression_*) are parser bugs found by review and fuzzing (and the
bad-input tests' reader inputs), as small files.

    Testing/Fuzz/make_corpus.py [--cfm-dir DIR] [--jacksboro FILE]
"""
import argparse
import ast
import os
import struct
import zipfile
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, "..", ".."))
CORPUS = os.path.join(HERE, "corpus")


def write(target, name, data):
    if isinstance(data, str):
        data = data.encode()
    os.makedirs(os.path.join(CORPUS, target), exist_ok=True)
    with open(os.path.join(CORPUS, target, name), "wb") as f:
        f.write(data)


# ---------------------------------------------------------------- .npy and .npz
def npy(descr, fortran, shape, payload, version=1):
    """A .npy file as numpy writes it (header padded to a multiple of 64)."""
    header = "{'descr': '%s', 'fortran_order': %s, 'shape': (%s), }" % (descr, fortran, shape)
    prefix = 8 + (2 if version == 1 else 4)
    header += " " * ((64 - (prefix + len(header) + 1) % 64) % 64) + "\n"
    size = struct.pack("<H", len(header)) if version == 1 else struct.pack("<I", len(header))
    return b"\x93NUMPY" + bytes([version, 0]) + size + header.encode("latin-1") + payload


def f8(*values):
    return struct.pack("<%dd" % len(values), *values)


def scalar(value):
    return npy("<f8", "False", "", f8(value))


def deflate(data):
    c = zlib.compressobj(9, zlib.DEFLATED, -zlib.MAX_WBITS, 9)
    return c.compress(data) + c.flush()


def zip_archive(entries):
    """A zip as numpy.savez writes it. entries: (name, data, deflated, claimed size or None)."""
    out, directory = b"", b""
    for name, data, deflated, claimed in entries:
        packed = deflate(data) if deflated else data
        size = len(data) if claimed is None else claimed
        crc = zlib.crc32(data) & 0xFFFFFFFF
        offset = len(out)
        method = 8 if deflated else 0
        out += struct.pack("<IHHHHHIIIHH", 0x04034B50, 20, 0, method, 0, 0x21, crc,
                           len(packed), size, len(name), 0) + name.encode() + packed
        directory += struct.pack("<IHHHHHHIIIHHHHHII", 0x02014B50, 20, 20, 0, method, 0, 0x21,
                                 crc, len(packed), size, len(name), 0, 0, 0, 0, 0, offset)
        directory += name.encode()
    start = len(out)
    out += directory
    out += struct.pack("<IHHHHIIH", 0x06054B50, 0, 0, len(entries), len(entries),
                       len(directory), start, 0)
    return out


def dem(elevation, deflated=False, bounds=(-84.5, -84.4, 36.3, 36.2), extra=()):
    names = ("xmin", "xmax", "ymin", "ymax")
    entries = [("elevation.npy", elevation, deflated, None)]
    entries += [(n + ".npy", scalar(v), deflated, None) for n, v in zip(names, bounds)]
    return zip_archive(entries + list(extra))


TWELVE = f8(*range(1, 13))
ELEVATION_3X4 = npy("<f8", "False", "3, 4", TWELVE)

# The .npy findings: (file name, descr, fortran_order, shape, payload).
BAD_NPY = [
    ("regression_shape_product_overflows", "<f8", "False", "9223372036854775811, 4", TWELVE),
    ("regression_rows_beyond_int", "<f8", "False", "4294967299, 0", b""),
    ("regression_fractional_shape", "<f8", "False", "3.5, 4", TWELVE),
    ("regression_negative_shape", "<f8", "False", "-3, 4", TWELVE),
    ("regression_fortran_order_not_a_boolean", "<f8", "NotFalseAtAll", "3, 4", TWELVE),
    ("regression_descr_with_trailing_junk", "<f8junk", "False", "3, 4", TWELVE),
    ("regression_payload_longer_than_shape", "<f8", "False", "3, 3", TWELVE),
]


def npz_and_npy(jacksboro):
    # Seeds: .npy of every supported kind, both header versions.
    write("npy", "seed_f8_3x4.npy", ELEVATION_3X4)
    write("npy", "seed_scalar_f8.npy", scalar(-84.5))
    write("npy", "seed_i2_2x3.npy", npy("<i2", "False", "2, 3", struct.pack("<6h", 1, -2, 3, -4, 5, 600)))
    write("npy", "seed_u1_v2_4.npy", npy("|u1", "False", "4,", bytes([0, 1, 254, 255]), version=2))
    write("npy", "seed_f4_v3_2x2.npy", npy("<f4", "False", "2, 2", struct.pack("<4f", 1.5, -2.5, 3e38, 0), version=3))
    write("npy", "seed_i8_empty.npy", npy("<i8", "False", "0, 3", b""))
    write("npy", "seed_u4_i4_1x2.npy", npy("<u4", "False", "1, 2", struct.pack("<2I", 7, 4294967295)))
    for name, descr, fortran, shape, payload in BAD_NPY:
        write("npy", name + ".npy", npy(descr, fortran, shape, payload))

    # Seeds: DEM archives, stored and deflated, with numpy's extra entries.
    write("npz", "seed_dem_3x4_stored.npz", dem(ELEVATION_3X4))
    write("npz", "seed_dem_3x4_deflated.npz", dem(ELEVATION_3X4, deflated=True))
    write("npz", "seed_dem_i1_zeros_deflated.npz",
          dem(npy("|i1", "False", "40, 50", bytes(2000)), deflated=True,
              extra=[("dx.npy", scalar(0.001), True, None), ("dy.npy", scalar(0.001), True, None)]))
    if jacksboro and os.path.exists(jacksboro):
        z = zipfile.ZipFile(jacksboro)
        raw = z.read("elevation.npy")
        length = struct.unpack("<H", raw[8:10])[0]
        header = ast.literal_eval(raw[10:10 + length].decode("latin-1"))
        rows, cols = header["shape"]
        values = struct.unpack("<%dh" % (rows * cols), raw[10 + length:])
        crop = [values[r * cols + c] for r in range(100, 106) for c in range(200, 207)]
        bounds = [struct.unpack("<d", z.read(n + ".npy")[-8:])[0] for n in ("xmin", "xmax", "ymin", "ymax")]
        # The crop's own bounds: rows 100-105 and columns 200-206 of the full grid.
        lon = lambda c: bounds[0] + c * (bounds[1] - bounds[0]) / (cols - 1)
        lat = lambda r: bounds[2] + r * (bounds[3] - bounds[2]) / (rows - 1)
        write("npz", "seed_jacksboro_crop_6x7.npz",
              dem(npy("<i2", "False", "6, 7", struct.pack("<42h", *crop)), deflated=True,
                  bounds=(lon(200), lon(206), lat(100), lat(105))))

    # Regressions (the archive around the bad .npy).
    # 1: a 1 KB archive whose deflated entry claims 0xfffffffe bytes (zeroed 4 GB).
    write("npz", "regression_claims_4gb_uncompressed.npz",
          zip_archive([("elevation.npy", ELEVATION_3X4, True, 0xFFFFFFFE)]))
    write("npz", "regression_stored_sizes_differ.npz",
          zip_archive([("elevation.npy", ELEVATION_3X4, False, 0x7FFFFFFF)]))
    # 3: a zero-size stored entry (memcpy from a null pointer), and a deflated one.
    for deflated, name in ((False, "stored"), (True, "deflated")):
        entries = [("elevation.npy", ELEVATION_3X4, deflated, None), ("xmin.npy", b"", deflated, None)]
        entries += [(n + ".npy", scalar(1.0), deflated, None) for n in ("xmax", "ymin", "ymax")]
        write("npz", "regression_zero_size_%s_entry.npz" % name, zip_archive(entries))
    # 4: bad .npy headers inside a DEM archive, and bounds that project to infinity.
    for name, descr, fortran, shape, payload in BAD_NPY:
        write("npz", name + ".npz", dem(npy(descr, fortran, shape, payload)))
    write("npz", "regression_infinite_projected_bounds.npz",
          dem(ELEVATION_3X4, bounds=(-1e308, 1e308, 36.3, 36.2)))


# ---------------------------------------------------------------- TSurf
def cfm_excerpt(path, vertices=12):
    """The header of a CFM file, its first `vertices` VRTX lines and the TRGL lines among them."""
    head, vrtx, trgl = [], [], []
    kept = set()
    with open(path) as f:
        for line in f:
            t = line.split()
            if t and t[0] == "VRTX":
                if len(vrtx) < vertices:
                    vrtx.append(line)
                    kept.add(t[1])
            elif t and t[0] == "TRGL":
                if all(i in kept for i in t[1:4]):
                    trgl.append(line)
            elif t and t[0] == "END":
                break
            elif not vrtx:
                head.append(line)
    return "".join(head + vrtx + trgl) + "END\n"


def tsurf(cfm_dir):
    if cfm_dir and os.path.isdir(cfm_dir):
        for source, name in (("Almanor.ts", "seed_cfm_almanor.ts"), ("Yaquina.ts", "seed_cfm_yaquina.ts"),
                             ("mccrory_2012_cascadia_interface.ts", "seed_cfm_mccrory_cascadia.ts")):
            write("tsurf", name, cfm_excerpt(os.path.join(cfm_dir, source)))
    write("tsurf", "seed_properties_atoms_depth.ts", "\r\n".join([
        "# what the writer writes, and what other GOCAD tools do",
        "GOCAD TSurf 1", "HEADER {", "name:two faces", "}",
        "GOCAD_ORIGINAL_COORDINATE_SYSTEM", "NAME Default", 'AXIS_NAME "X" "Y" "Z"',
        'AXIS_UNIT "m" "m" "m"', "ZPOSITIVE Depth", "END_ORIGINAL_COORDINATE_SYSTEM",
        "PROPERTIES Malleability Normal", "ESIZES 1 3", "NO_DATA_VALUES -99999 -99999",
        "TFACE", "PVRTX 1 0 0 10 0.5 0 0 1", "PVRTX 2 1 0 10 -99999 0 0 1",
        "PVRTX 3 0 1 10.5 1 0 0 1", "ATOM 4 1", "TRGL 1 2 3", "TFACE",
        "PVRTX 5 1 1 11 0.25 0 0.6 0.8", "TRGL 4 2 5", "BSTONE 1", "BORDER 6 1 2", "END",
        "GOCAD PLine 1", "HEADER {name:skipped}", "VRTX 1 0 0 0", "END",
        "GOCAD TSurf 1", "HEADER {name:second}", "PROPERTIES Labels", "VRTX 1 5 5 5",
        "PVRTX 2 6 5 5 3", "PVRTX 3 5 6 5 4", "TRGL 1 2 3", "END", ""]))
    # Regressions (scaled down): 64 properties of ESIZES 16, one PVRTX
    # giving them, then 200 VRTX lines padded with 1,024 NaN each (the finding: ESIZES
    # 1024 and 3,000 VRTX, 3.2 GB from 179 KB); and a property new to a second surface
    # padded on 1,000 earlier points.
    s = "GOCAD TSurf 1\nPROPERTIES" + "".join(" p%d" % i for i in range(64))
    s += "\nESIZES" + " 16" * 64 + "\nPVRTX 1 0 0 0" + " 0" * (64 * 16) + "\n"
    s += "".join("VRTX %d 0 0 0\n" % i for i in range(2, 202)) + "END\n"
    write("tsurf", "regression_esizes_padding_beyond_file_size.ts", s)
    s = "GOCAD TSurf 1\n" + "".join("VRTX %d 0 0 0\n" % i for i in range(1, 1001))
    s += "END\nGOCAD TSurf 1\nPROPERTIES spectrum\nESIZES 1024\nPVRTX 1 0 0 0" + " 0" * 1024 + "\nEND\n"
    write("tsurf", "regression_backfill_beyond_file_size.ts", s)
    # Item 9: a property with an empty name (was lost on write then read).
    write("tsurf", "regression_empty_property_name.ts",
          'GOCAD TSurf 1\nPROPERTIES "" a\nPVRTX 1 0 0 0 1 2\nPVRTX 2 1 0 0 3 4\n'
          'PVRTX 3 0 1 0 5 6\nTRGL 1 2 3\nEND\n')


# ---------------------------------------------------------------- traces
def traces():
    for source, name, lines in (("Data/Traces/grasp_drag.trace", "seed_grasp_drag.trace", 70),
                                ("Data/Demo/grasp_and_drag.trace", "seed_demo_grasp_and_drag.trace", 40)):
        path = os.path.join(REPO, source)
        if os.path.exists(path):
            with open(path) as f:
                write("trace", name, "".join(f.readlines()[:lines]))
    write("trace", "seed_two_buttons_and_turn.trace",
          "# t x y z qw qx qy qz buttons\n0 0 0 0 1 0 0 0 0\n0.5 0.01 0 0 0.9659258262890683 0 0 "
          "0.25881904510252074 1\n0.5 0.01 0 0 2 0 0 0 3   # equal times, unnormalised\n"
          "1 -0.02 0.005 1e-3 0 1 0 0 2\n")
    # Item 9: positions of 1e308 (interpolating between them overflowed to inf), and the
    # other refusals of the parser.
    write("trace", "regression_positions_1e308.trace",
          "0 -1e308 0 0 1 0 0 0 0\n1 1e308 1e308 -1e308 1 0 0 0 1\n")
    write("trace", "regression_time_goes_backwards.trace", "1 0 0 0 1 0 0 0 0\n0.5 0 0 0 1 0 0 0 0\n")
    write("trace", "regression_zero_quaternion.trace", "0 0 0 0 0 0 0 0 0\n")
    write("trace", "regression_nan_and_overflow.trace", "0 nan 0 0 1 0 0 0 0\n1 1e999 0 0 1 0 0 0 0\n")
    write("trace", "regression_buttons_out_of_range.trace", "0 0 0 0 1 0 0 0 4294967296\n")


# ---------------------------------------------------------------- raster metadata
def raster_input(crs, nodata, header, samples):
    """fuzz_raster's input: CRS line, no-data line, 8 header bytes, the samples."""
    return crs.encode() + b"\n" + nodata.encode() + b"\n" + bytes(header) + bytes(
        v & 0xFF for v in samples)


def rasters():
    # 5 x 4 pixels (bytes 3, 2), stride 1, cell data, origin (-84, 36) and 0.05 x -0.05
    # pixels (bytes -56 x 1.5, 48 x 0.75, 5 x 0.01, -5 x 0.01); -9 and 127 (NaN) are holes.
    wgs84 = "+proj=longlat +datum=WGS84 +no_defs"
    samples = [10, 12, 14, -9, 18, 11, 13, 15, 17, 19, 127, 14, 16, 18, 20, 13, 15, 17, 19, 21]
    write("raster", "seed_wgs84_nodata.bin", raster_input(wgs84, "-9", [3, 2, 0, 0, 200, 48, 5, 251], samples))
    write("raster", "seed_utm_hidden_stride2.bin",
          raster_input("+proj=utm +zone=16 +datum=WGS84 +units=m +no_defs", "nan",
                       [3, 2, 1, 2, 10, 20, 100, 100], [10 + k % 3 for k in range(20)]))
    write("raster", "seed_us_feet_point_data.bin",
          raster_input("+proj=lcc +lat_0=34.3333333333333 +lon_0=-86 +lat_1=36.4166666666667 "
                       "+lat_2=35.25 +x_0=600000 +y_0=0 +datum=NAD83 +units=us-ft +no_defs", "",
                       [3, 2, 0, 1, 10, 20, 100, 156], samples))
    write("raster", "seed_wkt_4326.bin", raster_input(
        'GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,298.257223563]],'
        'PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433]]', "-3.4028234663852886e+38",
        [3, 2, 0, 0, 200, 48, 5, 251], samples))
    write("raster", "seed_nad27_south.bin", raster_input("+proj=longlat +datum=NAD27 +no_defs", "0",
                                                          [14, 14, 0, 0, 120, 140, 3, 3], samples))
    for name, crs in (("no_crs", ""), ("geocentric", "+proj=geocent +datum=WGS84"),
                      ("paris_meridian", "+proj=longlat +ellps=clrk80ign +pm=paris"),
                      ("not_a_crs", "+proj=nonsense +zone=99")):
        write("raster", "seed_refused_%s.bin" % name, raster_input(crs, "", [3, 2, 0, 0, 200, 48, 5, 251], samples))
    write("raster", "seed_epsg_code.bin", raster_input("EPSG:32616", "", [3, 2, 0, 0, 10, 20, 100, 156], samples))
    write("raster", "seed_refused_nodata_text.bin", raster_input(wgs84, "1e999", [3, 2, 0, 0, 0, 0, 5, 5], samples))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cfm-dir", default=os.path.join(REPO, "..", "shared", "data", "crescent-cfm"))
    parser.add_argument("--jacksboro",
                        default="/usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz")
    args = parser.parse_args()
    npz_and_npy(args.jacksboro)
    tsurf(args.cfm_dir)
    traces()
    rasters()


if __name__ == "__main__":
    main()

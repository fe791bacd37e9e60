#!/usr/bin/python3
"""Writes the seeds of fuzz_merge into corpus/merge/: one studio folder tree per seed, in the
layout fuzz_merge.cpp reads (one byte per choice, front to back):
  - the kind of filmic, luts/sub, a, a/b (0 real, 2 a link out, 3 a relative link out, 4 a link to luts);
  - a file count, then per file: folder (a link to a folder: the folder it names), name, kind
    (FILE below; 1 is followed by a length and bytes);
  - a search-path entry count, then the entries (ENTRY below);
  - the config's name (0 studio.ocio, 1 config.ocio);
  - -o (OUT below), and for OUT["out"] what it holds first (0 absent, 1 empty, 2 a file, 3 a folder named as a set);
  - --prefix (index into kPrefixes); a second merge (0 none, 1 after a LUT changed, 2 unchanged);
  - cgtmo's agx.spi1d (0 as shipped, 6 a FIFO, 7 a link to /dev/zero).
Usage: tests/fuzz/make_merge_seeds.py"""
import os

OUT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "merge")
FOLDERS = {"luts": 0, "filmic": 1, "luts/sub": 2, "a": 3, "a/b": 4}
NAMES = {"film.spi1d": 0, "x.spi1d": 1, "y.cube": 2, "z.spi3d": 3}
FILE = {"lut": 0, "garbage": 1, "rel-link-out": 2, "abs-link-out": 3, "dev-zero": 4, "fifo": 5, "link-in": 6,
        "dangling": 7, "hard-link-out": 8, "link-to-x": 9, "link-to-folder-out": 10}
ENTRY = {"luts": 0, "filmic": 1, "luts/sub": 2, "a": 3, "a/b": 4, ".": 5, "..": 6, "../outside/dir": 7,
         "outside": 8, "$VAR/luts": 9, "./luts/": 10, "luts/../luts": 11}
OUT = {"nested": 0, "studio": 1, "studio/luts/merged": 2, "root": 3, "outside/merged": 4, "cgtmo-luts/merged": 5,
       "link-to-studio/merged": 6, "link-to-studio": 7, "out": 8}
PREFIX = {"cgtmo ": 0, "t ": 1, "-x ": 2, "+x ": 3, " x": 4, "a,b ": 5, "a:b ": 6, "x\t": 7}


def seed(folders=("real",) * 4, files=(), search=("luts", "filmic"), config_ocio=True, out="out", holds=0,
         prefix="cgtmo ", again=0, cgtmo_lut=0):
    kinds = {"real": 0, "link-out": 2, "rel-link-out": 3, "link-luts": 4}
    b = [kinds[f] for f in folders]
    b.append(len(files))
    for folder, name, kind, *text in files:
        b += [FOLDERS[folder], NAMES[name], FILE[kind]]
        if kind == "garbage":
            b.append(len(text[0]))
            b += list(text[0])
    assert len(files) <= 6 and len(search) <= 5, "fuzz_merge reads at most 6 files and 5 entries"
    b.append(len(search))
    b += [ENTRY[e] for e in search]
    b.append(1 if config_ocio else 0)
    b.append(OUT[out])
    if out == "out":
        b.append(holds)
    b += [PREFIX[prefix], again, cgtmo_lut]
    assert all(0 <= x < 256 for x in b)
    return bytes(b)


SEEDS = {
    # Merged: Blender's layout, then again after a studio LUT changed (the new set replaces the first).
    "seed-blender": seed(files=[("luts", "x.spi1d", "lut"), ("filmic", "y.cube", "lut")], again=1),
    "seed-duplicate-entries": seed(search=("luts", "filmic", "luts", "./luts/", "luts/../luts"), config_ocio=False, again=2),
    "seed-nested-output": seed(out="nested", files=[("luts/sub", "z.spi3d", "garbage", b"garbage")]),
    "seed-output-holds-files": seed(holds=2, again=1),
    "seed-output-holds-a-set-by-hand": seed(holds=3, again=1),
    "seed-hard-link-out": seed(files=[("luts", "x.spi1d", "hard-link-out")]),
    # Longer than the others: libFuzzer's length limit starts at the longest seed.
    "seed-many-files": seed(files=[("luts", "x.spi1d", "lut"), ("luts/sub", "y.cube", "garbage", b"LUT_3D_SIZE 2\n" + b"0 0 0\n" * 4),
                                   ("filmic", "z.spi3d", "link-in"), ("a", "x.spi1d", "fifo"), ("a/b", "y.cube", "lut"),
                                   ("filmic", "x.spi1d", "hard-link-out")],
                            search=("luts", "filmic", "luts/sub", "filmic", "a/b"), again=1),
    "seed-link-inside": seed(files=[("luts", "y.cube", "link-in"), ("luts/sub", "x.spi1d", "link-in")]),
    "seed-entries-made-absolute": seed(folders=("real", "real", "link-out", "real"), search=("a", ".", "$VAR/luts", "../outside/dir", "luts")),
    "seed-folder-loop": seed(folders=("real", "link-luts", "real", "real"), search=("luts", "luts/sub")),
    "regression-output-in-a-folder-not-read": seed(out="outside/merged", search=("luts",), again=1),
    # Refused: links out, FIFOs, devices (in a folder kept in place too: once a hang).
    "regression-fifo-in-a-folder-kept-in-place": seed(folders=("real", "real", "link-out", "real"), files=[("a", "x.spi1d", "fifo")],
                                                       search=("luts", "a")),
    "seed-dev-zero-in-a-folder-kept-in-place": seed(folders=("real", "real", "link-out", "real"), files=[("a", "x.spi1d", "dev-zero")],
                                                     search=("a",)),
    "seed-link-out": seed(files=[("luts/sub", "y.cube", "rel-link-out")], search=("luts",)),
    "seed-abs-link-out": seed(files=[("filmic", "film.spi1d", "abs-link-out")]),
    "seed-link-chain-out": seed(files=[("luts", "x.spi1d", "abs-link-out"), ("luts", "y.cube", "link-to-x")]),
    "seed-fifo": seed(files=[("luts", "y.cube", "fifo")]),
    "seed-dev-zero": seed(files=[("filmic", "z.spi3d", "dev-zero")]),
    "seed-dangling": seed(files=[("luts", "y.cube", "dangling")]),
    "seed-link-to-folder-out": seed(files=[("luts", "x.spi1d", "link-to-folder-out")]),
    "seed-subfolder-link-out": seed(folders=("real", "rel-link-out", "real", "real"), search=("luts", "luts/sub")),
    "seed-cgtmo-lut-fifo": seed(cgtmo_lut=6),
    "seed-cgtmo-lut-dev-zero": seed(cgtmo_lut=7),
    # Refused: -o where the merge reads, and look syntax in the prefix.
    "seed-output-is-studio": seed(out="studio", config_ocio=False),
    "seed-output-in-copied-folder": seed(out="studio/luts/merged"),
    "seed-output-holds-all": seed(out="root"),
    "seed-output-in-absolute-entry": seed(out="outside/merged", search=("luts", "outside")),
    "seed-output-in-cgtmo-luts": seed(out="cgtmo-luts/merged"),
    "seed-output-through-link": seed(out="link-to-studio/merged"),
    "seed-output-a-link-to-studio": seed(out="link-to-studio"),
    "seed-prefix-minus": seed(prefix="-x "),
    "seed-prefix-colon": seed(prefix="a:b ", again=1),
    "seed-prefix-tab": seed(prefix="x\t"),
}

if __name__ == "__main__":
    os.makedirs(OUT_DIR, exist_ok=True)
    for name in os.listdir(OUT_DIR):
        if name.startswith("seed"):
            os.remove(os.path.join(OUT_DIR, name))
    for name, data in SEEDS.items():
        with open(os.path.join(OUT_DIR, name), "wb") as f:
            f.write(data)
    print(f"{len(SEEDS)} seeds in {OUT_DIR}")

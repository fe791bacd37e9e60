#!/usr/bin/python3
"""`cgtmo bake --into` on real studio configs, in ociocheck and Blender, against `cgtmo apply`.

usage: check_into.py {blender|aces|hostile} CGTMO SOURCE_DIR WORK

- blender: Blender's shipped config; aces: an ACES-style config written here (reference
  ACES2065-1, scene_linear ACEScg, matrices derived from the primaries with Bradford adaptation,
  a LUT-based colour space in a luts/ folder, displays sRGB, Rec.1886, P3-D65 and XYZ).
- hostile: what a merge refuses, through the command line (exit 2 for a usage error, 1 for bad
  data, one line, nothing written): an output folder that is or is inside a folder the merge
  reads, a --prefix with look syntax, a link out of the studio's folder, cgtmo LUTs that are a
  FIFO or a link to /dev/zero, a config of nested YAML aliases (bake, apply --colorconfig, $OCIO);
  and what it does with a search-path entry that is a link to /etc and a folder named twice.
For blender and aces: the merge runs; `ociocheck --iconfig` reports no error on the merged config that it
does not report on the studio's; Blender (OCIO=merged config) loads it, offers every studio view
and look and every cgtmo view and look, and Image.save_render through cgtmo views equals
`cgtmo apply` of the same image within 1 code value at 8 bits. For the ACES-style config the
image handed to Blender is in ACEScg (the Rec.709 test image times the Rec.709 -> AP1 matrix,
stored as float); it is compared with `cgtmo apply --colorspace ACEScg` of that image, and with
`cgtmo apply` of those pixels converted back to linear Rec.709 by the studio config."""
import json, os, re, shutil, stat, subprocess, sys

import numpy as np
import OpenImageIO as oiio

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_apps import run, write_test_exr, compare, allowed_8bit, apply_args, read8  # noqa: E402

BLENDER_CONFIG = "/usr/share/blender/datafiles/colormanagement/config.ocio"
# Views rendered through Blender: one per LUT design.
RENDERED = ("reinhard", "agx", "drago", "pbr-neutral", "reinhard-jodie")


def xy_to_xyz(x, y):
    return np.array([x / y, 1.0, (1 - x - y) / y])


def rgb_to_xyz(primaries, white):
    p = np.stack([xy_to_xyz(*c) for c in primaries], axis=1)
    s = np.linalg.solve(p, xy_to_xyz(*white))
    return p * s


def bradford(src_white, dst_white):
    b = np.array([[0.8951, 0.2664, -0.1614], [-0.7502, 1.7135, 0.0367], [0.0389, -0.0685, 1.0296]])
    s, d = b @ xy_to_xyz(*src_white), b @ xy_to_xyz(*dst_white)
    return np.linalg.inv(b) @ np.diag(d / s) @ b


D60, D65 = (0.32168, 0.33767), (0.3127, 0.3290)
AP0 = ((0.7347, 0.2653), (0.0, 1.0), (0.0001, -0.0770))
AP1 = ((0.713, 0.293), (0.165, 0.830), (0.128, 0.044))
REC709 = ((0.64, 0.33), (0.30, 0.60), (0.15, 0.06))
P3 = ((0.680, 0.320), (0.265, 0.690), (0.150, 0.060))
REC2020 = ((0.708, 0.292), (0.170, 0.797), (0.131, 0.046))


def to_ap0(primaries, white):
    """RGB (primaries, white) -> ACES2065-1: to XYZ, Bradford to D60, to AP0."""
    m = rgb_to_xyz(primaries, white)
    if white != D60:
        m = bradford(white, D60) @ m
    return np.linalg.inv(rgb_to_xyz(AP0, D60)) @ m


def matrix_yaml(m, inverse=False):
    v = []
    for r in range(3):
        v += ["%.10g" % m[r][0], "%.10g" % m[r][1], "%.10g" % m[r][2], "0"]
    v += ["0", "0", "0", "1"]
    return "!<MatrixTransform> {matrix: [%s]%s}" % (", ".join(v), ", direction: inverse" if inverse else "")


def write_aces_style(folder):
    os.makedirs(os.path.join(folder, "luts"))
    with open(os.path.join(folder, "luts", "film.spi1d"), "w") as f:
        f.write("Version 1\nFrom 0.0 1.0\nLength 64\nComponents 1\n{\n")
        f.writelines("    %.8f\n" % (2 ** (10 * (i / 63.0) - 6) - 2 ** -6) for i in range(64))
        f.write("}\n")
    m709, mp3, mcg = to_ap0(REC709, D65), to_ap0(P3, D65), to_ap0(AP1, D60)
    xyz = bradford(D60, D65) @ rgb_to_xyz(AP0, D60)
    text = """ocio_profile_version: 2
search_path: luts
strictparsing: true
name: aces-style-studio
roles:
  scene_linear: ACEScg
  rendering: ACEScg
  aces_interchange: ACES2065-1
  cie_xyz_d65_interchange: CIE-XYZ-D65
  default: ACES2065-1
  default_byte: sRGB - Texture
  default_float: ACEScg
  default_sequencer: sRGB - Texture
  color_picking: sRGB - Texture
  texture_paint: sRGB - Texture
  data: Raw
  compositing_log: Film Log
file_rules:
  - !<Rule> {name: Textures, colorspace: sRGB - Texture, pattern: "*tex*", extension: "*"}
  - !<Rule> {name: Default, colorspace: default}
displays:
  sRGB:
    - !<View> {name: Un-tone-mapped, colorspace: sRGB - Display}
    - !<View> {name: Raw, colorspace: Raw}
  Rec.1886:
    - !<View> {name: Un-tone-mapped, colorspace: Rec.1886 - Display}
  P3-D65:
    - !<View> {name: Un-tone-mapped, colorspace: P3-D65 - Display}
  XYZ:
    - !<View> {name: Un-tone-mapped, colorspace: CIE-XYZ-D65}
active_displays: [sRGB, Rec.1886, P3-D65, XYZ]
active_views: [Un-tone-mapped, Raw]
looks:
  - !<Look>
    name: Warm
    process_space: ACEScg
    transform: %(warm)s
colorspaces:
  - !<ColorSpace>
    name: ACES2065-1
    family: ACES
  - !<ColorSpace>
    name: ACEScg
    family: ACES
    to_scene_reference: %(cg)s
  - !<ColorSpace>
    name: Linear Rec.709
    family: Utility
    to_scene_reference: %(lin709)s
  - !<ColorSpace>
    name: Linear Rec.2020
    family: Utility
    to_scene_reference: %(lin2020)s
  - !<ColorSpace>
    name: CIE-XYZ-D65
    family: Utility
    from_scene_reference: %(xyz)s
  - !<ColorSpace>
    name: Film Log
    family: Log
    to_scene_reference: !<GroupTransform>
      children:
        - !<FileTransform> {src: film.spi1d, interpolation: linear}
        - %(cg)s
  - !<ColorSpace>
    name: sRGB - Texture
    family: Utility
    to_scene_reference: !<GroupTransform>
      children:
        - !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055}
        - %(lin709)s
  - !<ColorSpace>
    name: sRGB - Display
    family: Display
    from_scene_reference: !<GroupTransform>
      children:
        - %(lin709inv)s
        - !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}
  - !<ColorSpace>
    name: Rec.1886 - Display
    family: Display
    from_scene_reference: !<GroupTransform>
      children:
        - %(lin709inv)s
        - !<ExponentTransform> {value: 2.4, direction: inverse}
  - !<ColorSpace>
    name: P3-D65 - Display
    family: Display
    from_scene_reference: !<GroupTransform>
      children:
        - %(p3inv)s
        - !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}
  - !<ColorSpace>
    name: Raw
    family: Utility
    isdata: true
""" % {"warm": matrix_yaml(np.diag([1.1, 1.0, 0.9])), "cg": matrix_yaml(mcg), "lin709": matrix_yaml(m709),
       "lin709inv": matrix_yaml(m709, True), "p3inv": matrix_yaml(mp3, True), "xyz": matrix_yaml(xyz),
       "lin2020": matrix_yaml(to_ap0(REC2020, D65))}
    path = os.path.join(folder, "studio.ocio")
    with open(path, "w") as f:
        f.write(text)
    # linear Rec.709 -> ACEScg, for the image Blender gets
    return path, np.linalg.inv(mcg) @ m709


def write_rgb(path, px):
    out = oiio.ImageOutput.create(path)
    out.open(path, oiio.ImageSpec(px.shape[1], px.shape[0], 3, oiio.FLOAT))
    out.write_image(px)
    out.close()


# A channel converted from float32 pixels is known to about 2^-24 of the sum of the magnitudes of
# the terms that make it (the storage rounding of each input), and a float32 conversion (OpenColorIO
# in Blender) adds as much again. cgtmo sets a channel within 2^-23 of that sum to 0 (storage
# residue); Blender keeps it. Where the channel is that small, the two disagree by what float32
# cannot hold, which a per-channel curve's toe shows (a pure red at 2^15 stored as ACEScg: a green
# of ~1e-3, 3 code values through reinhard). Those channels are reported, not held to 1 code value.
FLOAT32_RESOLUTION = 4 * 2.0 ** -24


def float32_undetermined(pixels, to_rec709):
    """Channels of `pixels` (H x W x 3 float32) converted by `to_rec709` that are within float32
    resolution of zero: boolean H x W x 3."""
    px = pixels.astype(np.float64)
    value = np.einsum("ij,hwj->hwi", to_rec709, px)
    magnitude = np.einsum("ij,hwj->hwi", np.abs(to_rec709), np.abs(px))
    return np.abs(value) <= FLOAT32_RESOLUTION * magnitude


def compare_determined(a_path, b_path, undetermined, label, failures, allowed=1):
    """compare() on the channels float32 determines; the others' largest difference is printed."""
    a, b = read8(a_path), read8(b_path)
    d = np.abs(a - b)
    held, rest = d[~undetermined], d[undetermined]
    worst = int(held.max()) if held.size else 0
    print("%-48s max diff %d code value(s)%s; %d channel(s) within float32 resolution of 0: max diff %d" %
          (label, worst, "" if worst <= allowed else ", %d values over" % int((held > allowed).sum()),
           int(rest.size), int(rest.max()) if rest.size else 0))
    if worst > allowed:
        failures.append(label)


def ocio_errors(config):
    r = subprocess.run(["ociocheck", "--iconfig", config], capture_output=True, text=True)
    lines = (r.stdout + r.stderr).splitlines()
    # An error names a colour space, view or file; the merged config's path differs from the studio's.
    return {re.sub(r"/\S*/", "/", l.strip()) for l in lines if "ERROR" in l.upper()}, r.returncode


BLENDER_SCRIPT = r'''
import sys, bpy
exr, work, colour_space, display, views, looks, rendered = sys.argv[sys.argv.index("--") + 1:]
scene = bpy.context.scene
vs = scene.view_settings
scene.display_settings.display_device = display
missing, found = [], []
for v in views.split("|"):
    try:
        vs.view_transform = v
        found.append(v)
    except TypeError:
        missing.append("view " + v)
vs.view_transform = views.split("|")[0]
for l in looks.split("|"):
    try:
        vs.look = l
        found.append(l)
    except TypeError:
        missing.append("look " + l)
print("cgtmo-check: view transforms and looks offered: " + ", ".join(found))
for m in missing:
    print("cgtmo-check: missing " + m)
img = bpy.data.images.load(exr)
img.colorspace_settings.name = colour_space
scene.render.image_settings.file_format = "PNG"
scene.render.image_settings.color_depth = "8"
scene.render.image_settings.color_mode = "RGB"
scene.render.dither_intensity = 0.0
for op in rendered.split("|"):
    vs.view_transform = "cgtmo " + op
    vs.look = "None"
    vs.exposure = 0.0
    vs.gamma = 1.0
    vs.use_curve_mapping = False
    img.save_render(work + "/" + op + "-blender.png", scene=scene)
print("cgtmo-check: ok")
'''


SMALL_STUDIO = """ocio_profile_version: 2
search_path: "%s"
roles:
  scene_linear: Linear
  default: Linear
  data: Raw
displays:
  sRGB:
    - !<View> {name: Standard, colorspace: sRGB}
    - !<View> {name: Raw, colorspace: Raw}
active_displays: []
active_views: []
colorspaces:
  - !<ColorSpace>
    name: Linear
  - !<ColorSpace>
    name: sRGB
    from_scene_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}
  - !<ColorSpace>
    name: Film
    to_scene_reference: !<FileTransform> {src: film.spi1d, interpolation: linear}
  - !<ColorSpace>
    name: Raw
    isdata: true
"""
FILM_LUT = "Version 1\nFrom 0.0 1.0\nLength 2\nComponents 1\n{\n0\n1\n}\n"


def nested_aliases(levels=10, width=10):
    """A config whose colour space c9 is width^levels transforms through aliases, in about 3 KB."""
    s = "ocio_profile_version: 2\nroles:\n  default: c0\n  scene_linear: c0\ncolorspaces:\n"
    for level in range(levels):
        kids = ", ".join("!<MatrixTransform> {}" if level == 0 else "*g%d" % (level - 1) for _ in range(width))
        s += "  - !<ColorSpace>\n    name: c%d\n    to_scene_reference: &g%d !<GroupTransform> {children: [%s]}\n" % (level, level, kids)
    return s


def tree_state(root):
    """Every entry under root, links not followed: type, inode, size, mtime and content."""
    state = {}
    for folder, dirs, files in os.walk(root):
        for name in dirs + files:
            p = os.path.join(folder, name)
            st = os.lstat(p)
            v = (st.st_mode, st.st_ino, st.st_size, st.st_mtime_ns)
            if stat.S_ISREG(st.st_mode):
                with open(p, "rb") as f:
                    v += (f.read(),)
            state[os.path.relpath(p, root)] = v
    return state


def hostile(cgtmo, src, work):
    """The refusals of bake --into, through the command line: exit status, one line, nothing written."""
    failures = []
    studio_dir = os.path.join(work, "studio")
    os.makedirs(os.path.join(studio_dir, "luts"))
    with open(os.path.join(studio_dir, "luts", "film.spi1d"), "w") as f:
        f.write(FILM_LUT)

    def write_studio(search, name="studio.ocio", text=None):
        path = os.path.join(studio_dir, name)
        with open(path, "w") as f:
            f.write(text if text is not None else SMALL_STUDIO % search)
        return path

    studio = write_studio("luts")
    cgtmo_config = os.path.join(src, "ocio_config", "config.ocio")

    def expect(label, code, args, wanted, env=None):
        before = tree_state(work)
        try:
            r = subprocess.run([cgtmo] + args, capture_output=True, text=True, timeout=120, env=env)
        except subprocess.TimeoutExpired:
            failures.append("%s: no answer in 120 s" % label)
            print("FAIL %s: no answer in 120 s" % label)
            return
        err = r.stderr.strip()
        ok = r.returncode == code and (code == 0 or (len(err.splitlines()) == 1 and wanted in err))
        written = code != 0 and tree_state(work) != before
        print("%s %s: exit %d, %s%s" % ("ok  " if ok and not written else "FAIL", label, r.returncode, err.splitlines()[-1] if err else "",
                                        " (something was written)" if written else ""))
        if not ok or written:
            failures.append(label)

    into = ["bake", "--into", studio, "--cgtmo-config", cgtmo_config, "-q", "-o"]
    # The studio's own folder, its config not named config.ocio; inside a folder the merge copies.
    expect("-o the studio's folder", 2, into + [studio_dir], "is the studio config's folder")
    expect("-o inside a copied LUT folder", 2, into + [os.path.join(studio_dir, "luts", "merged")], "which the merge reads")
    for prefix in ("-x ", "+x ", "a,b ", "a:b "):
        expect("--prefix %r" % prefix, 2, into + [os.path.join(work, "merged"), "--prefix", prefix], "--prefix")
    # A link out of the studio's folder in a copied folder.
    os.makedirs(os.path.join(work, "outside"))
    with open(os.path.join(work, "outside", "secret"), "w") as f:
        f.write("secret")
    link = os.path.join(studio_dir, "luts", "escape.spi1d")
    os.symlink("../../outside/secret", link)
    expect("a link out of the studio's folder", 1, into + [os.path.join(work, "merged")], "not to a file in that folder")
    os.remove(link)
    # cgtmo's LUT a FIFO, a link to /dev/zero: refused at once, never read.
    ours = os.path.join(work, "cgtmo")
    os.makedirs(os.path.join(ours, "luts"))
    os.makedirs(os.path.join(ours, "ocio_config"))
    shutil.copy(cgtmo_config, os.path.join(ours, "ocio_config"))
    for name in os.listdir(os.path.join(src, "luts")):
        if name.endswith((".spi1d", ".spi3d", ".ctf")):
            shutil.copy(os.path.join(src, "luts", name), os.path.join(ours, "luts"))
    lut = os.path.join(ours, "luts", "agx.spi1d")
    os.remove(lut)
    os.mkfifo(lut)
    ours_args = ["bake", "--into", studio, "-q", "--cgtmo-config", os.path.join(ours, "ocio_config", "config.ocio"), "-o"]
    expect("--cgtmo-config LUT a FIFO", 1, ours_args + [os.path.join(work, "merged")], "not a regular file (FIFO)")
    os.remove(lut)
    os.symlink("/dev/zero", lut)
    expect("--cgtmo-config LUT a link to /dev/zero", 1, ours_args + [os.path.join(work, "merged")], "not a regular file (character device)")
    # Nested YAML aliases: refused before OpenColorIO reads them, by every command that loads a config.
    laughs = write_studio("", "laughs.ocio", nested_aliases())
    exr = os.path.join(work, "in.exr")
    write_test_exr(exr)
    out_png = os.path.join(work, "out.png")
    expect("bake --into a config of nested aliases", 1, ["bake", "--into", laughs, "-q", "-o", os.path.join(work, "merged")], "expand it to")
    expect("apply --colorconfig a config of nested aliases", 1, ["apply", exr, "-o", out_png, "--colorconfig", laughs], "expand it to")
    expect("apply with $OCIO a config of nested aliases", 1, ["apply", exr, "-o", out_png], "expand it to", env=dict(os.environ, OCIO=laughs))
    # A search-path entry that is a link (to /etc) is not copied; a folder named twice is copied once.
    os.symlink("/etc", os.path.join(studio_dir, "system"))
    studio = write_studio("luts:system:luts")
    merged = os.path.join(work, "merged")
    expect("a search-path entry that is a link, a folder named twice", 0,
           ["bake", "--into", studio, "--cgtmo-config", cgtmo_config, "-q", "-o", merged], "")
    sets = [n for n in os.listdir(merged) if n.startswith("cgtmo-set-")]
    copied = sorted(os.listdir(os.path.join(merged, sets[0]))) if len(sets) == 1 else []
    print("merged folder: %s; the set holds %s" % (sorted(os.listdir(merged)), copied))
    if sorted(os.listdir(merged)) != sorted(["config.ocio"] + sets) or copied != [".cgtmo-set", "cgtmo-luts", "luts"]:
        failures.append("the merged folder holds more than config.ocio and one set of luts and cgtmo-luts")
    errors, rc = ocio_errors(os.path.join(merged, "config.ocio"))
    print("ociocheck on the merged config: exit %d, %d error line(s)" % (rc, len(errors)))
    if rc != 0 or errors:
        failures.append("ociocheck rejects the merged config")
    return failures


def main():
    which, cgtmo, src, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    if which == "hostile":
        failures = hostile(cgtmo, src, work)
        print("FAILED:", *failures, sep="\n  ") if failures else print("passed")
        return 1 if failures else 0
    cgtmo_config = os.path.join(src, "ocio_config", "config.ocio")
    manifest = json.load(open(os.path.join(src, "luts", "manifest.json")))["operators"]
    exr = os.path.join(work, "hdr-test.exr")
    write_test_exr(exr)
    failures = []

    if which == "blender":
        if not os.path.exists(BLENDER_CONFIG):
            print("Blender's config is not installed")
            return 77
        studio, to_scene_linear = BLENDER_CONFIG, None
        display, studio_views, studio_looks = "sRGB", ["Standard", "Filmic", "Filmic Log", "Raw", "False Color"], \
            ["Very High Contrast", "Medium Contrast", "Very Low Contrast"]
        scene_linear = "Linear"
    else:
        studio, to_scene_linear = write_aces_style(os.path.join(work, "studio"))
        display, studio_views, studio_looks = "sRGB", ["Un-tone-mapped", "Raw"], ["Warm"]
        scene_linear = "ACEScg"

    merged_dir = os.path.join(work, "merged")
    print(run([cgtmo, "bake", "--into", studio, "-o", merged_dir, "--cgtmo-config", cgtmo_config]))
    merged = os.path.join(merged_dir, "config.ocio")

    before, rc_before = ocio_errors(studio)
    after, rc_after = ocio_errors(merged)
    new = sorted(after - before)
    print("ociocheck: studio exit %d with %d error line(s), merged exit %d with %d" % (rc_before, len(before), rc_after, len(after)))
    if new or (rc_after != 0 and rc_before == 0):
        failures += ["ociocheck: new error: " + l for l in new] or ["ociocheck: merged config fails, studio's passes"]

    image = apply_input = exr
    if to_scene_linear is not None:
        # The same picture in ACEScg for Blender; cgtmo apply reads the Rec.709 original.
        buf = oiio.ImageBuf(exr)
        px = np.asarray(buf.get_pixels(oiio.FLOAT), np.float64)[..., :3]
        cg = np.einsum("ij,hwj->hwi", to_scene_linear, px).astype(np.float32)
        image = os.path.join(work, "hdr-test-acescg.exr")
        write_rgb(image, cg)
        # cgtmo apply reads linear Rec.709: the ACEScg pixels Blender gets, converted to the
        # studio's "Linear Rec.709" by OpenColorIO's CPU processor, as the merged look converts
        # them. Converted in double instead, pure reds above 30000 differ: OpenColorIO's float
        # matrices leave a green of about 0.002 there, which reinhard shows as 2-6 code values.
        import PyOpenColorIO as ocio
        cpu = ocio.Config.CreateFromFile(studio).getProcessor("ACEScg", "Linear Rec.709").getDefaultCPUProcessor()
        back = np.ascontiguousarray(cg.copy())
        cpu.applyRGB(back)
        apply_input = os.path.join(work, "hdr-test-acescg-as-rec709.exr")
        write_rgb(apply_input, back)
        undetermined = float32_undetermined(cg, np.linalg.inv(to_scene_linear))

    views = studio_views + ["cgtmo " + op for op in manifest]
    looks = studio_looks + ["cgtmo " + op for op in manifest]
    script = os.path.join(work, "blender_into.py")
    with open(script, "w") as f:
        f.write(BLENDER_SCRIPT)
    env = dict(os.environ, OCIO=merged)
    out = run(["blender", "-b", "--factory-startup", "--python", script, "--", image, work, scene_linear, display,
               "|".join(views), "|".join(looks), "|".join(RENDERED)], env=env)
    print("\n".join(l for l in out.splitlines() if l.startswith("cgtmo-check") or "Color management" in l))
    if "cgtmo-check: ok" not in out:
        failures.append("blender script did not finish")
    failures += [l for l in out.splitlines() if l.startswith("cgtmo-check: missing")]
    for op in RENDERED:
        ref = os.path.join(work, op + "-cgtmo.png")
        run(apply_args(cgtmo, apply_input, ref, cgtmo_config, op, manifest[op]["params"]))
        compare(ref, os.path.join(work, op + "-blender.png"), "blender (%s) view 'cgtmo %s'" % (which, op), failures,
                allowed_8bit(manifest[op]))
        if to_scene_linear is not None:
            # What a user runs on the same ACEScg render: cgtmo apply told its colour space.
            ref_cs = os.path.join(work, op + "-cgtmo-colorspace.png")
            run(apply_args(cgtmo, image, ref_cs, cgtmo_config, op, manifest[op]["params"], ("--colorspace", "ACEScg")))
            compare_determined(ref_cs, os.path.join(work, op + "-blender.png"), undetermined,
                               "blender (%s) view 'cgtmo %s' vs apply --colorspace" % (which, op), failures,
                               allowed_8bit(manifest[op]))

    if to_scene_linear is not None:
        # cgtmo apply inside the studio's config alone: the ACEScg file read as the config's
        # scene_linear (no --colorspace) and encoded by the studio's own sRGB display equals
        # the same run in cgtmo's config; its P3-D65 display gets a Display P3 profile.
        for op in RENDERED:
            studio_out = os.path.join(work, op + "-studio-config.png")
            run(apply_args(cgtmo, image, studio_out, studio, op, manifest[op]["params"],
                           ("--display", "sRGB", "--view", "Un-tone-mapped")))
            compare(os.path.join(work, op + "-cgtmo-colorspace.png"), studio_out,
                    "apply in the studio config (%s) vs cgtmo's config" % op, failures)
        p3 = os.path.join(work, "agx-studio-p3.png")
        out = run(apply_args(cgtmo, image, p3, studio, "agx", manifest["agx"]["params"],
                             ("--display", "P3-D65", "--view", "Un-tone-mapped", "--json")))
        tag = json.loads([l for l in out.splitlines() if l.startswith("{")][-1]).get("colour_tag", "")
        print("studio P3-D65 display, colour tag:", tag)
        if "0.6800,0.3200" not in tag:
            failures.append("studio P3-D65 display: no Display P3 profile (%s)" % tag)

    if failures:
        print("FAILED:", *failures, sep="\n  ")
        return 1
    print("passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""The eight test scenes, each aimed at one case the tone mapper must handle.

Each builder takes a fresh `scene_kit.Kit`, adds geometry, emitters (every one in a light group of
its own, the world included) and the camera. Units are metres; all geometry is procedural.
"""
import math
import random

WHITE = (0.73, 0.73, 0.73)


def cornell(k):
    """Cornell box with two spheres and Suzanne under one area light (bleeding between objects
    and walls). The box is open at the front, so the black world shows around it (background)."""
    white = k.diffuse("white", WHITE)
    red = k.diffuse("red", (0.63, 0.065, 0.05))
    green = k.diffuse("green", (0.14, 0.45, 0.091))
    k.wall("floor", (-1, -1, 0), (1, 0, 0), (0, 1, 0), 2, 2, white)
    k.wall("ceiling", (-1, -1, 2), (0, 1, 0), (1, 0, 0), 2, 2, white)
    k.wall("back", (-1, 1, 0), (1, 0, 0), (0, 0, 1), 2, 2, white)
    k.wall("left", (-1, -1, 0), (0, 1, 0), (0, 0, 1), 2, 2, red)
    k.wall("right", (1, -1, 0), (0, 0, 1), (0, 1, 0), 2, 2, green)
    k.sphere("sphere_diffuse", (-0.45, 0.35, 0.4), 0.4, k.diffuse("ivory", (0.8, 0.75, 0.6)))
    k.sphere("sphere_metal", (0.5, -0.25, 0.3), 0.3, k.diffuse("metal", (0.9, 0.9, 0.9), roughness=0.15, metallic=1.0))
    k.suzanne("suzanne", (0.35, 0.5, 0.85), 0.35, (0.0, 0.0, math.radians(200)), k.diffuse("yellow", (0.8, 0.6, 0.1)))
    k.boxes("pedestal", [((0.1, 0.2, 0.0), (0.6, 0.75, 0.5))], white)
    k.add_light("ceiling_light", "AREA", (0, 0, 1.99), power=40.0, size=(0.5, 0.5))  # faces down
    k.world((0.0, 0.0, 0.0), 0.0)
    k.camera((0, -3.6, 1.0), (0, 0, 1.0), lens_mm=32.0)


def two_rooms(k):
    """Two rooms joined by an open door. The only light is a ceiling panel in room B, placed where
    the camera in room A cannot see it: the image maximum is far below the light's luminance."""
    wall = k.diffuse("wall", (0.7, 0.68, 0.62))
    floor = k.diffuse("floor", (0.45, 0.3, 0.18), roughness=0.5)
    ceiling = k.diffuse("ceiling", (0.8, 0.8, 0.8))
    # Room A: x in [-4, 0]; room B: x in [0, 4]; both y in [0, 4], z in [0, 2.6].
    k.wall("floor", (-4, 0, 0), (1, 0, 0), (0, 1, 0), 8, 4, floor)
    k.wall("ceiling", (-4, 0, 2.6), (0, 1, 0), (1, 0, 0), 4, 8, ceiling)
    k.wall("south", (-4, 0, 0), (1, 0, 0), (0, 0, 1), 8, 2.6, wall)
    k.wall("north", (-4, 4, 0), (0, 0, 1), (1, 0, 0), 2.6, 8, wall)
    k.wall("west", (-4, 0, 0), (0, 1, 0), (0, 0, 1), 4, 2.6, wall)
    k.wall("east", (4, 0, 0), (0, 0, 1), (0, 1, 0), 2.6, 4, wall)
    # The dividing wall (one two-sided plane) with a door y in [1.5, 2.5], z < 2.1.
    k.wall("divider_a", (0, 0, 0), (0, 0, 1), (0, 1, 0), 2.6, 4, wall, holes=[(0, 1.5, 2.1, 2.5)])
    k.boxes("door_frame", [((-0.05, 1.42, 0), (0.05, 1.5, 2.1)), ((-0.05, 2.5, 0), (0.05, 2.58, 2.1)),
                           ((-0.05, 1.42, 2.1), (0.05, 2.58, 2.18))], k.diffuse("frame", (0.35, 0.22, 0.12)))
    # Furniture in both rooms, so light reaches room A by several bounces.
    k.boxes("table_b", [((1.5, 1.6, 0.72), (2.7, 2.6, 0.78)), ((1.55, 1.65, 0), (1.62, 1.72, 0.72)),
                        ((2.58, 1.65, 0), (2.65, 1.72, 0.72)), ((1.55, 2.48, 0), (1.62, 2.55, 0.72)),
                        ((2.58, 2.48, 0), (2.65, 2.55, 0.72))], k.diffuse("wood", (0.5, 0.33, 0.2)))
    k.sphere("ball_b", (3.2, 1.0, 0.35), 0.35, k.diffuse("blue", (0.15, 0.25, 0.6)))
    k.boxes("cabinet_a", [((-3.95, 0.3, 0), (-3.45, 1.5, 1.1))], k.diffuse("grey", (0.35, 0.35, 0.35)))
    k.sphere("ball_a", (-1.2, 1.2, 0.3), 0.3, k.diffuse("orange", (0.7, 0.35, 0.1)))
    k.add_light("room_b_light", "AREA", (3.2, 3.3, 2.58), power=300.0, size=(0.6, 0.6))
    k.world((0.0, 0.0, 0.0), 0.0)
    k.camera((-3.5, 3.5, 1.3), (0.0, 1.9, 0.9), lens_mm=24.0)


def sun_window(k):
    """A room seen from inside: sky and a sunlit patch through a window, a dark alcove. The sun
    and sky are about 1e5 times brighter than the alcove's back."""
    plaster = k.diffuse("plaster", (0.7, 0.7, 0.68))
    floor = k.diffuse("floor", (0.12, 0.09, 0.06), roughness=0.5)  # dark oak: less light bounced inside
    dark = k.diffuse("dark", (0.01, 0.01, 0.01), roughness=0.9, specular=0.1)
    # Room x in [-2.5, 2.5], y in [0, 5], z in [0, 2.7]; window in the north wall (y = 5).
    k.wall("floor", (-2.5, 0, 0), (1, 0, 0), (0, 1, 0), 5, 5, floor)
    k.wall("ceiling", (-2.5, 0, 2.7), (0, 1, 0), (1, 0, 0), 5, 5, plaster)
    k.wall("south", (-2.5, 0, 0), (1, 0, 0), (0, 0, 1), 5, 2.7, plaster)
    k.wall("north", (-2.5, 5, 0), (0, 0, 1), (1, 0, 0), 2.7, 5, plaster, holes=[(0.6, 0.8, 2.2, 2.7)])
    k.wall("west", (-2.5, 0, 0), (0, 1, 0), (0, 0, 1), 5, 2.7, plaster)
    # East wall with a narrow opening into a deep, dark alcove (x in [2.5, 6]).
    k.wall("east", (2.5, 0, 0), (0, 0, 1), (0, 1, 0), 2.7, 5, plaster, holes=[(0, 3.2, 2.0, 4.2)])
    k.boxes("alcove", [((2.5, 3.1, 0), (6.1, 3.2, 2.1)), ((2.5, 4.2, 0), (6.1, 4.3, 2.1)),
                       ((6.0, 3.1, 0), (6.1, 4.3, 2.1)), ((2.5, 3.1, 2.0), (6.1, 4.3, 2.1))], dark)
    k.wall("alcove_floor", (2.5, 3.2, 0.001), (1, 0, 0), (0, 1, 0), 3.5, 1.0, dark)
    # Window frame, a sill and some furniture.
    k.boxes("window_frame", [((-1.7, 4.95, 0.55), (0.2, 5.1, 0.6)), ((-1.7, 4.95, 2.2), (0.2, 5.1, 2.25)),
                             ((-0.775, 4.98, 0.6), (-0.725, 5.05, 2.2))], k.diffuse("frame", (0.8, 0.8, 0.8)))
    k.boxes("sofa", [((-2.4, 1.0, 0), (-1.6, 3.0, 0.45)), ((-2.5, 1.0, 0), (-2.2, 3.0, 0.9))],
            k.diffuse("fabric", (0.2, 0.3, 0.5)))
    k.boxes("table", [((-0.9, 2.2, 0.4), (0.3, 3.0, 0.45)), ((-0.85, 2.25, 0), (-0.8, 2.3, 0.4)),
                      ((0.2, 2.25, 0), (0.25, 2.3, 0.4)), ((-0.85, 2.9, 0), (-0.8, 2.95, 0.4)),
                      ((0.2, 2.9, 0), (0.25, 2.95, 0.4))], k.diffuse("wood", (0.45, 0.3, 0.18)))
    # Outside: a lawn and a house across the street, both in the sun.
    k.wall("lawn", (-30, 5, -0.01), (1, 0, 0), (0, 1, 0), 60, 40, k.diffuse("grass", (0.12, 0.25, 0.06)))
    k.boxes("house", [((-8, 18, 0), (6, 22, 6))], k.diffuse("house", (0.75, 0.7, 0.6)))
    # Sun from the north, 40 degrees up, so it shines through the window onto the floor.
    elevation, azimuth = math.radians(40), math.radians(200)
    k.add_light("sun", "SUN", (0, 0, 10), strength=20.0, colour=(1.0, 0.95, 0.88),
                rotation=(math.pi / 2 - elevation, 0.0, azimuth))
    k.world((0.45, 0.6, 1.0), 1.5)
    k.camera((0.3, 0.3, 1.45), (0.6, 4.0, 1.2), lens_mm=18.0)


def night(k):
    """A street at night: tiny, very bright lamps and neon strips in a mostly dark frame."""
    k.wall("road", (-20, -5, 0), (1, 0, 0), (0, 1, 0), 40, 30, k.diffuse("asphalt", (0.05, 0.05, 0.05), roughness=0.6))
    k.wall("facade", (-20, 6, 0), (1, 0, 0), (0, 0, 1), 40, 12, k.diffuse("brick", (0.18, 0.09, 0.06)))
    k.boxes("kerb", [((-20, 4.5, 0), (20, 6, 0.15))], k.diffuse("concrete", (0.3, 0.3, 0.3)))
    pole = k.diffuse("pole", (0.1, 0.1, 0.1), roughness=0.3, metallic=1.0)
    for i, x in enumerate((-5.0, 4.0)):
        k.cylinder("pole_%d" % (i + 1), (x, 4.8, 0), (x, 4.8, 4.0), 0.06, pole)
        bulb = k.sphere("lamp_%d" % (i + 1), (x, 4.8, 4.08), 0.06, pole, segments=16)
        k.emissive(bulb, (1.0, 0.78, 0.45), 3000.0)
    # Neon sign on the facade: a pink frame and a cyan zig-zag, thin tubes.
    pink = []
    for a, b in [((-2, 5.95, 2.2), (1.5, 5.95, 2.2)), ((1.5, 5.95, 2.2), (1.5, 5.95, 3.4)),
                 ((1.5, 5.95, 3.4), (-2, 5.95, 3.4)), ((-2, 5.95, 3.4), (-2, 5.95, 2.2))]:
        pink.append(k.cylinder("neon_pink_part", a, b, 0.02, pole, segments=8))
    cyan = []
    pts = [(-1.7 + 0.45 * i, 5.95, 2.45 if i % 2 == 0 else 3.15) for i in range(8)]
    for a, b in zip(pts[:-1], pts[1:]):
        cyan.append(k.cylinder("neon_cyan_part", a, b, 0.015, pole, segments=8))
    import bpy
    for parts, name, colour, strength in ((pink, "neon_pink", (1.0, 0.05, 0.35), 60.0),
                                          (cyan, "neon_cyan", (0.05, 0.85, 1.0), 40.0)):
        bpy.ops.object.select_all(action="DESELECT")
        for p in parts:
            p.select_set(True)
        bpy.context.view_layer.objects.active = parts[0]
        bpy.ops.object.join()
        parts[0].name = name
        k.emissive(parts[0], colour, strength)
    # A lit window far up the facade and a small lamp inside a doorway.
    win = k.quad("window_lit", [(6, 5.99, 5), (6, 5.99, 6.2), (7.2, 5.99, 6.2), (7.2, 5.99, 5)], pole)
    k.emissive(win, (1.0, 0.85, 0.6), 4.0)
    k.add_light("door_lamp", "POINT", (-7.0, 5.7, 2.6), power=40.0, radius=0.03, colour=(1.0, 0.6, 0.3))
    k.world((0.02, 0.03, 0.08), 0.05)
    k.camera((0.5, -6.0, 1.6), (0.0, 6.0, 2.6), lens_mm=26.0)


def relief(k, seed=7):
    """A brick wall with a carved panel under raking sunlight (detail preservation)."""
    rnd = random.Random(seed)
    k.wall("mortar", (-3, 0.0, 0), (1, 0, 0), (0, 0, 1), 6, 3.2, k.diffuse("mortar", (0.55, 0.52, 0.47)))
    brick_mats = [k.diffuse("brick_%d" % i, c, roughness=0.85) for i, c in
                  enumerate([(0.45, 0.17, 0.1), (0.52, 0.22, 0.12), (0.38, 0.15, 0.1)])]
    lists = [[], [], []]
    bw, bh, gap = 0.215, 0.065, 0.012
    row = 0
    z = 0.0
    while z < 3.2:
        x = -3.0 - (bw / 2 if row % 2 else 0.0)
        while x < 3.0:
            x0, x1 = max(x, -3.0), min(x + bw, 3.0)
            # Leave the panel's niche free of bricks.
            if not (-0.9 < (x0 + x1) / 2 < 0.9 and 0.7 < z + bh / 2 < 2.1):
                depth = 0.04 + rnd.uniform(-0.006, 0.006)
                lists[rnd.randrange(3)].append(((x0, -depth, z), (x1, 0.0, z + bh)))
            x += bw + gap
        z += bh + gap
        row += 1
    for i, boxes in enumerate(lists):
        k.boxes("bricks_%d" % i, boxes, brick_mats[i])
    # The carved panel: a height field (rosette, rings and a wave border) in a stone niche.
    n_u, n_v, w, h = 240, 186, 1.8, 1.4
    verts, faces = [], []
    for j in range(n_v + 1):
        for i in range(n_u + 1):
            u, v = i / n_u, j / n_v
            x, zz = -0.9 + u * w, 0.7 + v * h
            cx, cz = x, zz - 1.4
            r = math.hypot(cx, cz)
            a = math.atan2(cz, cx)
            height = 0.0
            if r < 0.55:
                height += 0.025 * max(0.0, math.cos(8 * a)) * (1 - r / 0.55) + 0.012 * math.cos(r * 40)
            border = min(u, 1 - u, v, 1 - v)
            if border < 0.08:
                height += 0.015 * (0.5 + 0.5 * math.sin(60 * (u + v)))
            verts.append((x, -height - 0.002, zz))
    for j in range(n_v):
        for i in range(n_u):
            a = j * (n_u + 1) + i
            faces.append((a, a + n_u + 1, a + n_u + 2, a + 1))
    k.mesh("relief_panel", verts, faces, k.diffuse("stone", (0.7, 0.66, 0.58), roughness=0.9), smooth=True)
    k.wall("ground", (-3, -3, 0), (1, 0, 0), (0, 1, 0), 6, 3, k.diffuse("gravel", (0.3, 0.28, 0.25)))
    # Raking sun from the left, 8 degrees off the wall's plane.
    k.add_light("sun", "SUN", (0, -2, 3), strength=6.0, colour=(1.0, 0.93, 0.82),
                rotation=(math.radians(70), 0.0, math.radians(-82)))
    k.world((0.5, 0.62, 0.85), 0.3)
    k.camera((0.0, -4.2, 1.5), (0.0, 0.0, 1.45), lens_mm=35.0)


def colored_lights(k):
    """Saturated red, green and blue spots on white walls, overlapping, and a blue emissive panel
    (hue of luminance-based versus per-channel operators)."""
    white = k.diffuse("white", (0.8, 0.8, 0.8))
    k.wall("floor", (-3, 0, 0), (1, 0, 0), (0, 1, 0), 6, 5, white)
    k.wall("ceiling", (-3, 0, 3), (0, 1, 0), (1, 0, 0), 5, 6, white)
    k.wall("back", (-3, 5, 0), (0, 0, 1), (1, 0, 0), 3, 6, white)
    k.wall("left", (-3, 0, 0), (0, 1, 0), (0, 0, 1), 5, 3, white)
    k.wall("right", (3, 0, 0), (0, 0, 1), (0, 1, 0), 3, 5, white)
    k.wall("front", (-3, 0, 0), (1, 0, 0), (0, 0, 1), 6, 3, white)
    k.sphere("sphere", (-0.8, 3.2, 0.5), 0.5, white)
    k.boxes("cube", [((0.5, 2.8, 0), (1.3, 3.6, 0.8))], white)
    for name, colour, x in (("spot_red", (1.0, 0.0, 0.0), -1.0), ("spot_green", (0.0, 1.0, 0.0), 0.0),
                            ("spot_blue", (0.0, 0.0, 1.0), 1.0)):
        # Aim each spot from near the camera at a point on the back wall: the three pools overlap.
        from mathutils import Vector
        src, dst = Vector((x * 1.6, 0.6, 2.6)), Vector((x * 0.5, 5.0, 1.4))
        rot = (dst - src).to_track_quat("-Z", "Y").to_euler()
        k.add_light(name, "SPOT", tuple(src), power=1500.0, colour=colour, radius=0.05,
                    spot_size=math.radians(40), spot_blend=0.2, rotation=tuple(rot), visible_to_camera=False)
    panel = k.quad("panel_blue", [(2.99, 3.6, 1.2), (2.99, 3.6, 2.0), (2.99, 4.4, 2.0), (2.99, 4.4, 1.2)], white)
    k.emissive(panel, (0.05, 0.1, 1.0), 12.0)
    k.world((0.0, 0.0, 0.0), 0.0)
    k.camera((0.0, 0.4, 1.5), (0.0, 5.0, 1.2), lens_mm=18.0)


def lit_box(k):
    """A lit room seen from a dark street through a wide shop window: the view is mostly the
    bright interior, while the sphere around the camera (the probe) is mostly dark night."""
    wall = k.diffuse("wall", (0.75, 0.72, 0.66))
    k.wall("ground", (-30, -30, 0), (1, 0, 0), (0, 1, 0), 60, 60, k.diffuse("asphalt", (0.06, 0.06, 0.06), roughness=0.6))
    # Room x in [-2, 2], y in [0, 4], z in [0, 2.6]; the window is in the front wall (y = 0).
    k.wall("floor", (-2, 0, 0.002), (1, 0, 0), (0, 1, 0), 4, 4, k.diffuse("floor", (0.5, 0.35, 0.2), roughness=0.5))
    k.wall("ceiling", (-2, 0, 2.6), (0, 1, 0), (1, 0, 0), 4, 4, wall)
    k.wall("back", (-2, 4, 0), (0, 0, 1), (1, 0, 0), 2.6, 4, wall)
    k.wall("left", (-2, 0, 0), (0, 1, 0), (0, 0, 1), 4, 2.6, k.diffuse("teal", (0.2, 0.5, 0.5)))
    k.wall("right", (2, 0, 0), (0, 0, 1), (0, 1, 0), 2.6, 4, wall)
    k.wall("front", (-2, 0, 0), (1, 0, 0), (0, 0, 1), 4, 2.6, k.diffuse("facade", (0.3, 0.28, 0.26)),
           holes=[(0.6, 0.4, 3.4, 2.1)])
    k.boxes("shelf", [((-1.9, 2.6, 0), (-1.5, 3.9, 1.8)), ((1.5, 2.6, 0), (1.9, 3.9, 1.8))],
            k.diffuse("wood", (0.45, 0.3, 0.18)))
    k.boxes("counter", [((-0.9, 1.6, 0), (0.9, 2.1, 0.9))], k.diffuse("red", (0.6, 0.08, 0.06)))
    k.sphere("globe", (0.4, 1.85, 1.1), 0.2, k.diffuse("ivory", (0.8, 0.75, 0.6)))
    k.add_light("shop_light", "AREA", (0, 2.2, 2.58), power=400.0, size=(1.0, 1.0))
    k.world((0.01, 0.015, 0.03), 0.05)
    k.camera((0.3, -3.2, 1.4), (0.0, 2.0, 1.1), lens_mm=28.0)


def dark_doorway(k):
    """From an unlit room, a brightly lit room seen through an open door: the frame is centred on
    the bright doorway while the sphere around the camera is the dark room."""
    wall = k.diffuse("wall", (0.6, 0.58, 0.55))
    # Room A is panelled in dark wood, so little of room B's light comes back from it.
    dark = k.diffuse("panelling", (0.05, 0.035, 0.025), roughness=0.6)
    # Room A (dark): x in [-4, 0]; room B (lit): x in [0, 5]; both y in [0, 4], z in [0, 2.6].
    k.wall("floor_a", (-4, 0, 0), (1, 0, 0), (0, 1, 0), 4, 4, dark)
    k.wall("ceiling_a", (-4, 0, 2.6), (0, 1, 0), (1, 0, 0), 4, 4, dark)
    k.wall("south_a", (-4, 0, 0), (1, 0, 0), (0, 0, 1), 4, 2.6, dark)
    k.wall("north_a", (-4, 4, 0), (0, 0, 1), (1, 0, 0), 2.6, 4, dark)
    k.wall("west_a", (-4, 0, 0), (0, 1, 0), (0, 0, 1), 4, 2.6, dark)
    k.wall("floor_b", (0, 0, 0), (1, 0, 0), (0, 1, 0), 5, 4, k.diffuse("floor", (0.4, 0.27, 0.16), roughness=0.5))
    k.wall("ceiling_b", (0, 0, 2.6), (0, 1, 0), (1, 0, 0), 4, 5, k.diffuse("ceiling", (0.8, 0.8, 0.8)))
    k.wall("south_b", (0, 0, 0), (1, 0, 0), (0, 0, 1), 5, 2.6, wall)
    k.wall("north_b", (0, 4, 0), (0, 0, 1), (1, 0, 0), 2.6, 5, wall)
    k.wall("east", (5, 0, 0), (0, 0, 1), (0, 1, 0), 2.6, 4, k.diffuse("yellow", (0.75, 0.6, 0.25)))
    # The dividing wall: dark on room A's side, plaster on room B's (two planes 2 mm apart).
    k.wall("divider_a", (-0.002, 0, 0), (0, 0, 1), (0, 1, 0), 2.6, 4, dark, holes=[(0, 1.4, 2.2, 2.6)])
    k.wall("divider_b", (0.002, 0, 0), (0, 0, 1), (0, 1, 0), 2.6, 4, wall, holes=[(0, 1.4, 2.2, 2.6)])
    k.boxes("door_frame", [((-0.05, 1.32, 0), (0.05, 1.4, 2.2)), ((-0.05, 2.6, 0), (0.05, 2.68, 2.2)),
                           ((-0.05, 1.32, 2.2), (0.05, 2.68, 2.28))], k.diffuse("frame", (0.35, 0.22, 0.12)))
    k.boxes("table_b", [((2.4, 1.5, 0.72), (3.6, 2.5, 0.78)), ((2.45, 1.55, 0), (2.52, 1.62, 0.72)),
                        ((3.48, 1.55, 0), (3.55, 1.62, 0.72)), ((2.45, 2.38, 0), (2.52, 2.45, 0.72)),
                        ((3.48, 2.38, 0), (3.55, 2.45, 0.72))], k.diffuse("white", (0.8, 0.8, 0.8)))
    k.sphere("ball_b", (3.0, 2.0, 0.98), 0.2, k.diffuse("blue", (0.15, 0.25, 0.6)))
    k.boxes("armchair_a", [((-1.6, 0.2, 0), (-0.8, 1.0, 0.45)), ((-1.6, 0.2, 0), (-0.8, 0.35, 0.95))],
            k.diffuse("fabric", (0.3, 0.15, 0.12)))
    k.add_light("room_b_light", "AREA", (3.0, 2.0, 2.58), power=600.0, size=(1.0, 1.0))
    k.world((0.0, 0.0, 0.0), 0.0)
    k.camera((-1.5, 2.1, 1.45), (2.0, 2.0, 1.25), lens_mm=24.0)


SCENES = {
    "cornell": cornell,
    "two-rooms": two_rooms,
    "sun-window": sun_window,
    "night": night,
    "relief": relief,
    "colored-lights": colored_lights,
    "lit-box": lit_box,
    "dark-doorway": dark_doorway,
}

"""Building blocks for the procedural test scenes: materials, meshes, lights, light groups.

Runs inside Blender (imports bpy). Every emitter goes through `add_light` or `emissive_mesh`, which
put it in a light group of its own and record what the sidecar needs, so no scene can forget one.

Emitted radiance, in the render's own units (Cycles scene-linear Rec.709, the values the EXR holds
for a directly visible emitter), per emitter kind; luminance is Rec.709 Y of that radiance:
  POINT, SPOT  L = P / (4 pi^2 r^2) * colour     (P watts, r = radius: a sphere seen as a disk of
                                                  area pi r^2 with intensity P / (4 pi) W/sr; a spot
                                                  has the intensity of a point light of the same P)
  AREA         L = P / (4 A) * colour            (A = size_x * size_y, or pi/4 * size_x * size_y for
                                                  DISK and ELLIPSE; Blender 3.4, spread 180 degrees)
  SUN          L = S / (pi tan^2(angle / 2))     (S = strength, the irradiance on a surface facing the
                 * colour                         sun; the disk of angular diameter `angle` carries it)
  MESH         L = strength * colour             (Emission shader)
  WORLD        L = strength * colour             (uniform Background shader)
POINT, SPOT, AREA and MESH were measured on Blender 3.4.1 with a directly visible emitter
(100 W area 1x1 m: 25.0; 100 W point r 0.5 m: 10.132; emission strength 3: 3.0). A sun is never
seen by camera rays; its irradiance convention was measured instead (strength 2 on a white
Lambertian plane: 2/pi = 0.6366) and the disk radiance follows from the geometry.
"""
import math

import bpy

REC709_Y = (0.2126, 0.7152, 0.0722)


def luminance(rgb):
    return sum(w * c for w, c in zip(REC709_Y, rgb))


def emitted_radiance(kind, colour, power=None, radius=None, area=None, strength=None, angle=None):
    """Radiance (RGB) an emitter of this kind shows to a camera ray, with the formula used."""
    if kind in ("POINT", "SPOT"):
        scale = power / (4.0 * math.pi ** 2 * radius ** 2)
        formula = "P / (4 pi^2 r^2)"
    elif kind == "AREA":
        scale = power / (4.0 * area)
        formula = "P / (4 A)"
    elif kind == "SUN":
        scale = strength / (math.pi * math.tan(angle / 2.0) ** 2)
        formula = "S / (pi tan^2(angle/2))"
    elif kind in ("MESH", "WORLD"):
        scale = strength
        formula = "strength"
    else:
        raise ValueError("unknown emitter kind " + kind)
    return [scale * c for c in colour], formula


class Kit:
    """Holds the scene being built and the emitters recorded for the sidecar."""

    def __init__(self):
        for obj in list(bpy.data.objects):
            bpy.data.objects.remove(obj)
        self.scene = bpy.context.scene
        self.view_layer = self.scene.view_layers[0]
        self.emitters = []  # dicts for the sidecar, in creation order
        self._materials = {}

    # ---- light groups ----------------------------------------------------------------------
    def _group(self, name):
        if name not in [g.name for g in self.view_layer.lightgroups]:
            self.view_layer.lightgroups.add(name=name)
        return name

    # ---- materials -------------------------------------------------------------------------
    def diffuse(self, name, rgb, roughness=0.7, specular=0.3, metallic=0.0):
        key = ("diffuse", name)
        if key in self._materials:
            return self._materials[key]
        m = bpy.data.materials.new(name)
        m.use_nodes = True
        b = m.node_tree.nodes["Principled BSDF"]
        b.inputs["Base Color"].default_value = (*rgb, 1.0)
        b.inputs["Roughness"].default_value = roughness
        b.inputs["Specular"].default_value = specular
        b.inputs["Metallic"].default_value = metallic
        self._materials[key] = m
        return m

    def emission(self, name, rgb, strength):
        m = bpy.data.materials.new(name)
        m.use_nodes = True
        nt = m.node_tree
        nt.nodes.clear()
        e = nt.nodes.new("ShaderNodeEmission")
        e.inputs["Color"].default_value = (*rgb, 1.0)
        e.inputs["Strength"].default_value = strength
        out = nt.nodes.new("ShaderNodeOutputMaterial")
        nt.links.new(e.outputs[0], out.inputs["Surface"])
        return m

    # ---- geometry --------------------------------------------------------------------------
    def mesh(self, name, verts, faces, material, smooth=False):
        me = bpy.data.meshes.new(name)
        me.from_pydata([tuple(v) for v in verts], [], [tuple(f) for f in faces])
        me.update()
        if smooth:
            for p in me.polygons:
                p.use_smooth = True
        me.materials.append(material)
        obj = bpy.data.objects.new(name, me)
        self.scene.collection.objects.link(obj)
        return obj

    def quad(self, name, corners, material):
        """One quad; corners counter-clockwise seen from the side its normal points to."""
        return self.mesh(name, corners, [(0, 1, 2, 3)], material)

    def box(self, name, lo, hi, material):
        """Closed axis-aligned box with outward normals."""
        (x0, y0, z0), (x1, y1, z1) = lo, hi
        v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
             (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
        f = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
        return self.mesh(name, v, f, material)

    def boxes(self, name, boxes, material):
        """Many boxes (lo, hi) in one mesh object (bricks, shelves)."""
        verts, faces = [], []
        for (x0, y0, z0), (x1, y1, z1) in boxes:
            b = len(verts)
            verts += [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
                      (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
            faces += [tuple(b + i for i in f) for f in
                      [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]]
        return self.mesh(name, verts, faces, material)

    def wall(self, name, origin, u, v, size_u, size_v, material, holes=()):
        """A planar wall: origin + s*u + t*v for s in [0,size_u], t in [0,size_v], normal u x v.
        `holes` are (s0, t0, s1, t1) rectangles left open (doors, windows); the wall is cut into
        the rectangles of the grid their edges make, minus the holes."""
        ss = sorted({0.0, size_u, *[h[0] for h in holes], *[h[2] for h in holes]})
        ts = sorted({0.0, size_v, *[h[1] for h in holes], *[h[3] for h in holes]})
        verts, faces = [], []

        def point(s, t):
            return tuple(origin[i] + s * u[i] + t * v[i] for i in range(3))

        for i in range(len(ss) - 1):
            for j in range(len(ts) - 1):
                cs, ct = 0.5 * (ss[i] + ss[i + 1]), 0.5 * (ts[j] + ts[j + 1])
                if any(h[0] <= cs <= h[2] and h[1] <= ct <= h[3] for h in holes):
                    continue
                b = len(verts)
                verts += [point(ss[i], ts[j]), point(ss[i + 1], ts[j]), point(ss[i + 1], ts[j + 1]), point(ss[i], ts[j + 1])]
                faces.append((b, b + 1, b + 2, b + 3))
        return self.mesh(name, verts, faces, material)

    def sphere(self, name, centre, radius, material, segments=48):
        bpy.ops.mesh.primitive_uv_sphere_add(segments=segments, ring_count=segments // 2, radius=radius, location=centre)
        obj = bpy.context.object
        obj.name = name
        bpy.ops.object.shade_smooth()
        obj.data.materials.append(material)
        return obj

    def cylinder(self, name, a, b, radius, material, segments=16):
        """A capped cylinder from point a to point b."""
        ax = [b[i] - a[i] for i in range(3)]
        length = math.sqrt(sum(c * c for c in ax))
        mid = [(a[i] + b[i]) / 2 for i in range(3)]
        bpy.ops.mesh.primitive_cylinder_add(vertices=segments, radius=radius, depth=length, location=mid)
        obj = bpy.context.object
        obj.name = name
        # Rotate +Z onto the axis.
        from mathutils import Vector
        obj.rotation_mode = "QUATERNION"
        obj.rotation_quaternion = Vector((0, 0, 1)).rotation_difference(Vector(ax).normalized())
        bpy.ops.object.shade_smooth()
        obj.data.materials.append(material)
        return obj

    def suzanne(self, name, location, scale, rotation, material):
        bpy.ops.mesh.primitive_monkey_add(size=2.0 * scale, location=location, rotation=rotation)
        obj = bpy.context.object
        obj.name = name
        mod = obj.modifiers.new("subdiv", "SUBSURF")
        mod.levels = 2
        mod.render_levels = 2
        bpy.ops.object.shade_smooth()
        obj.data.materials.append(material)
        return obj

    # ---- emitters --------------------------------------------------------------------------
    def add_light(self, name, kind, location, power=None, colour=(1.0, 1.0, 1.0), radius=0.1, size=(1.0, 1.0),
                  shape="RECTANGLE", strength=None, angle=math.radians(0.526), spot_size=math.radians(45),
                  spot_blend=0.15, rotation=(0.0, 0.0, 0.0), visible_to_camera=True):
        """A Blender light in a light group of its own (named after it)."""
        data = bpy.data.lights.new(name, kind)
        data.color = colour
        rec = {"name": name, "type": kind, "lightgroup": self._group(name), "color": list(colour),
               "visible_to_camera": bool(visible_to_camera)}
        if kind == "SUN":
            data.energy = strength
            data.angle = angle
            rec.update(strength=strength, angle=angle)
            rgb, formula = emitted_radiance(kind, colour, strength=strength, angle=angle)
            rec["irradiance"] = strength
        elif kind == "AREA":
            data.energy = power
            data.shape = shape
            data.size = size[0]
            data.size_y = size[1]
            area = size[0] * size[1] * (math.pi / 4.0 if shape in ("DISK", "ELLIPSE") else 1.0)
            rec.update(power=power, shape=shape, size=list(size), area=area)
            rgb, formula = emitted_radiance(kind, colour, power=power, area=area)
        else:  # POINT, SPOT
            data.energy = power
            data.shadow_soft_size = radius
            rec.update(power=power, radius=radius)
            if kind == "SPOT":
                data.spot_size = spot_size
                data.spot_blend = spot_blend
                rec.update(spot_size=spot_size, spot_blend=spot_blend)
            rgb, formula = emitted_radiance(kind, colour, power=power, radius=radius)
        obj = bpy.data.objects.new(name, data)
        obj.location = location
        obj.rotation_euler = rotation
        obj.visible_camera = visible_to_camera
        obj.lightgroup = rec["lightgroup"]
        self.scene.collection.objects.link(obj)
        rec.update(radiance=rgb, luminance=luminance(rgb), formula=formula, object=obj)
        self.emitters.append(rec)
        return obj

    def emissive(self, obj, colour, strength):
        """Turns a mesh object into an emitter (Emission shader) in a light group of its own."""
        obj.data.materials.clear()
        obj.data.materials.append(self.emission(obj.name + "_emission", colour, strength))
        obj.lightgroup = self._group(obj.name)
        rgb, formula = emitted_radiance("MESH", colour, strength=strength)
        dims = list(obj.dimensions)
        self.emitters.append({"name": obj.name, "type": "MESH", "lightgroup": obj.name, "color": list(colour),
                              "strength": strength, "size": dims, "visible_to_camera": True,
                              "radiance": rgb, "luminance": luminance(rgb), "formula": formula, "object": obj})
        return obj

    def world(self, colour, strength, group="world"):
        """Uniform background; always its own light group (all zero when strength is 0)."""
        w = bpy.data.worlds.new("world")
        self.scene.world = w
        w.use_nodes = True
        bg = w.node_tree.nodes["Background"]
        bg.inputs["Color"].default_value = (*colour, 1.0)
        bg.inputs["Strength"].default_value = strength
        w.lightgroup = self._group(group)
        rgb, formula = emitted_radiance("WORLD", colour, strength=strength)
        self.emitters.append({"name": "world", "type": "WORLD", "lightgroup": group, "color": list(colour),
                              "strength": strength, "visible_to_camera": True,
                              "radiance": rgb, "luminance": luminance(rgb), "formula": formula, "object": None})

    # ---- camera ----------------------------------------------------------------------------
    def camera(self, location, look_at, lens_mm=28.0, sensor_mm=36.0, clip=(0.05, 100.0)):
        from mathutils import Vector
        cam = bpy.data.cameras.new("camera")
        cam.lens = lens_mm
        cam.sensor_width = sensor_mm
        cam.sensor_fit = "HORIZONTAL"
        cam.clip_start, cam.clip_end = clip
        obj = bpy.data.objects.new("camera", cam)
        obj.location = location
        direction = Vector(look_at) - Vector(location)
        obj.rotation_mode = "QUATERNION"
        obj.rotation_quaternion = direction.to_track_quat("-Z", "Y")
        self.scene.collection.objects.link(obj)
        self.scene.camera = obj
        return obj

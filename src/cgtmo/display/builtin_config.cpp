#include "cgtmo/display/display.h"

namespace cgtmo::display {

const char* builtin_config_yaml() {
  return R"(ocio_profile_version: 2.1

name: cgtmo-builtin
description: cgtmo's built-in display encodings, used when neither --colorconfig nor $OCIO is set.
search_path: ""
strictparsing: true

roles:
  default: Linear Rec.709
  reference: Linear Rec.709
  scene_linear: Linear Rec.709
  data: Raw
  color_picking: sRGB
  texture_paint: sRGB
  color_timing: sRGB
  compositing_log: sRGB

file_rules:
  - !<Rule> {name: Default, colorspace: default}

displays:
  sRGB:
    - !<View> {name: Standard, colorspace: sRGB}
    - !<View> {name: Raw, colorspace: Raw}
  Rec.1886:
    - !<View> {name: Standard, colorspace: Rec.1886}
    - !<View> {name: Raw, colorspace: Raw}
  Display P3:
    - !<View> {name: Standard, colorspace: Display P3}
    - !<View> {name: Raw, colorspace: Raw}

active_displays: [sRGB, Rec.1886, Display P3]
active_views: [Standard, Raw]

colorspaces:
  - !<ColorSpace>
    name: Linear Rec.709
    aliases: [Linear, lin_rec709]
    family: Linear
    description: Scene-linear Rec.709 primaries, D65 (Blender's scene linear).
    isdata: false
    encoding: scene-linear

  - !<ColorSpace>
    name: sRGB
    family: Display
    description: Piecewise sRGB encoding (IEC 61966-2-1) of display-linear Rec.709.
    isdata: false
    encoding: sdr-video
    from_scene_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}

  - !<ColorSpace>
    name: Rec.1886
    family: Display
    description: Pure 2.4 gamma encoding (ITU-R BT.1886 with black 0) of display-linear Rec.709.
    isdata: false
    encoding: sdr-video
    from_scene_reference: !<ExponentTransform> {value: 2.4, direction: inverse}

  - !<ColorSpace>
    name: Display P3
    family: Display
    description: Display P3 (P3 primaries, D65, sRGB encoding) of display-linear Rec.709.
    isdata: false
    encoding: sdr-video
    from_scene_reference: !<GroupTransform>
      children:
        - !<MatrixTransform> {matrix: [0.8224621, 0.177538, 0, 0, 0.0331941, 0.9668058, 0, 0, 0.0170827, 0.0723974, 0.9105199, 0, 0, 0, 0, 1]}
        - !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}

  - !<ColorSpace>
    name: Raw
    family: Data
    description: Data passed through unchanged.
    isdata: true
    encoding: data
)";
}

}  // namespace cgtmo::display

// The Whitted scene of issue 27's table (tools/bench/scenes/whitted_plane.json) for POV-Ray 3.7:
// a plane, a mirror sphere and a glass sphere, one point light, depth 5; camera, light and
// spheres as stage 05's whitted.json, the checkerboard's 120 boxes replaced by one plane.
// POV-Ray is left-handed (z into the screen), so every z is negated.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.2 max_trace_level 6 }

// rt's "fov": 40 is vertical; POV-Ray's angle is horizontal (4:3 image).
camera {
  perspective
  location <0, 1.4, -7>
  look_at <0, 0.6, 0>
  right x * image_width / image_height
  angle 2 * degrees(atan(tan(radians(20)) * image_width / image_height))
}
background { color rgb <0.25, 0.45, 0.85> }
// rt: intensity 80 over distance squared; POV-Ray: 2 / (1 + (d / fade_distance)^fade_power).
light_source { <2, 7, -6> color rgb 40 fade_distance 1 fade_power 2 }

plane {
  y, -1
  texture { pigment { rgb <0.8, 0.1, 0.05> } finish { ambient 1 diffuse 1 } }
}
sphere {
  <-1.1, 0.4, 1.5>, 1.1
  pigment { rgb 0.05 }
  finish { ambient 0 diffuse 1 specular 0.8 roughness 1 / 200 reflection 0.8 }
}
sphere {
  <0.7, 1, -0.6>, 0.9
  pigment { rgbf <1, 1, 1, 0.85> }
  finish { ambient 0 diffuse 0 specular 0.8 roughness 1 / 200 reflection 0.1 }
  interior { ior 1.5 }
}

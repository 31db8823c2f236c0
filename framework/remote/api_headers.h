// Every declaration the call lists (stage_api/calls.h) name: the stage APIs and the render/
// functions that call them.
#pragma once

#include "render/accelerate.h"
#include "render/background.h"
#include "render/camera_ray.h"
#include "render/ray_tree.h"
#include "render/render.h"
#include "render/sampled.h"
#include "render/shade.h"
#include "render/texturing.h"
#include "stage_api/calls.h"
#include "stage_api/stage01.h"
#include "stage_api/stage02.h"
#include "stage_api/stage03.h"
#include "stage_api/stage04.h"
#include "stage_api/stage05.h"
#include "stage_api/stage06.h"
#include "stage_api/stage07.h"
#include "stage_api/stage08.h"
#include "stage_api/stage10.h"

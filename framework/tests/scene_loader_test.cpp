#include <gtest/gtest.h>
#include "scene/scene_loader.h"
TEST(Placeholder, X) {}

// Writes the closed cylinder of stages/05-recursion/scenes/cylinder.obj (committed; rerun only
// to change it):  g++ -std=c++20 -O2 scripts/make_cylinder_obj.cpp -o /tmp/cyl && /tmp/cyl > stages/05-recursion/scenes/cylinder.obj
// Axis y, radius 1, y from -1 to 1, `segments` sides; faces counter-clockwise seen from outside.
#include <cmath>
#include <cstdio>

int main() {
    const int segments = 32;
    const double pi = 3.14159265358979323846;
    std::printf(
        "# closed cylinder: radius 1, y in [-1, 1], %d segments (scripts/make_cylinder_obj.cpp)\n",
        segments);
    for (int i = 0; i < segments; ++i) {  // vertices 1..2n: bottom and top rings, interleaved
        const double a = 2 * pi * i / segments;
        std::printf("v %.6f -1 %.6f\nv %.6f 1 %.6f\n", std::cos(a), -std::sin(a), std::cos(a),
                    -std::sin(a));
    }
    std::printf("v 0 -1 0\nv 0 1 0\n");  // cap centres: 2n+1, 2n+2
    const int bottom_center = 2 * segments + 1, top_center = 2 * segments + 2;
    for (int i = 0; i < segments; ++i) {
        const int j = (i + 1) % segments;
        const int b0 = 2 * i + 1, t0 = 2 * i + 2, b1 = 2 * j + 1, t1 = 2 * j + 2;
        // Angle grows counter-clockwise seen from +y (x = cos a, z = -sin a).
        std::printf("f %d %d %d\nf %d %d %d\n", b0, b1, t1, b0, t1, t0);
        std::printf("f %d %d %d\n", top_center, t0, t1);
        std::printf("f %d %d %d\n", bottom_center, b1, b0);
    }
}

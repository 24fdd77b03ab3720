/*
 * The C reference for `npm run bench`: the work of render() on the class scene
 * (lib/scene/examples.js, 640x480, fov 30, eye at the origin looking down -z) in plain
 * C, one thread: per pixel the primary ray, the nearest of the 7 spheres, then
 * for each of the 2 emissive spheres (the lights) a shadow ray and Lambert's
 * cos term; the background where nothing is hit. Same formulas as
 * lib/math/camera.js, lib/shapes/sphere.js (hit) and lib/tracing/trace.js, in doubles.
 *
 *   cc -O3 -march=native -o reference bench/reference.c -lm
 *   ./reference FRAMES [out.rgba]   prints one line per frame: milliseconds
 *
 * bench/bench.js compiles and runs it, alternating with render(), and
 * compares its bytes with render()'s.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define W 640
#define H 480
#define N 7
#define EPSILON 1e-6
#define TANGENT 1e-12
#define BIAS 1e-4

typedef struct { double x, y, z; } vec;
typedef struct { vec c; double r2; vec color; vec emission; } sphere;

static sphere spheres[N];
static int lights[N], nlights = 0;
static const vec background = { 2, 2, 2 };
static unsigned char frame[W * H * 4];

static void add(int i, double x, double y, double z, double r, vec color, double emission) {
  spheres[i] = (sphere){ { x, y, z }, r * r, color, { emission, emission, emission } };
  if (emission > 0) lights[nlights++] = i;
}

/* Sphere.hit: the geometric route, smallest t > tMin, else INFINITY. */
static inline double hit(const sphere *s, vec o, vec d, double tMin) {
  double Lx = s->c.x - o.x, Ly = s->c.y - o.y, Lz = s->c.z - o.z;
  double tca = Lx * d.x + Ly * d.y + Lz * d.z;
  double LL = Lx * Lx + Ly * Ly + Lz * Lz;
  double gap = s->r2 - (LL - tca * tca);
  double band = TANGENT * (s->r2 + LL);
  if (gap < -band) return INFINITY;
  double thc = gap <= band ? 0 : sqrt(gap);
  if (tca - thc > tMin) return tca - thc;
  return tca + thc > tMin ? tca + thc : INFINITY;
}

static unsigned char byte(double c) { /* Uint8ClampedArray: clamp, round half to even */
  double v = c * 255;
  if (!(v > 0)) return 0;
  if (v >= 255) return 255;
  return (unsigned char)nearbyint(v);
}

static void render(void) {
  const double halfHeight = tan(30 * (M_PI / 180) / 2), halfWidth = halfHeight * W / H;
  const vec eye = { 0, 0, 0 };
  for (int y = 0; y < H; y++) {
    for (int x = 0; x < W; x++) {
      double sx = (2 * (x + 0.5) / W - 1) * halfWidth, sy = (1 - 2 * (y + 0.5) / H) * halfHeight;
      vec d = { sx * 1 + sy * 0 + 0, sx * 0 + sy * 1 + 0, sx * 0 + sy * 0 + -1 };
      double len = sqrt(d.x * d.x + d.y * d.y + d.z * d.z), k = len > 0 ? 1 / len : 0;
      d.x *= k; d.y *= k; d.z *= k;
      double nearest = INFINITY; int found = -1;
      for (int i = 0; i < N; i++) {
        double t = hit(&spheres[i], eye, d, EPSILON);
        if (t < nearest) { nearest = t; found = i; }
      }
      vec out = background;
      if (found >= 0) {
        const sphere *s = &spheres[found];
        vec P = { d.x * nearest, d.y * nearest, d.z * nearest };
        vec Nn = { P.x - s->c.x, P.y - s->c.y, P.z - s->c.z };
        double nl = sqrt(Nn.x * Nn.x + Nn.y * Nn.y + Nn.z * Nn.z), nk = nl > 0 ? 1 / nl : 0;
        Nn.x *= nk; Nn.y *= nk; Nn.z *= nk;
        if (d.x * Nn.x + d.y * Nn.y + d.z * Nn.z > 0) { Nn.x = -Nn.x; Nn.y = -Nn.y; Nn.z = -Nn.z; }
        out = s->emission; /* + ambient 0 */
        for (int l = 0; l < nlights; l++) {
          const sphere *light = &spheres[lights[l]];
          if (light == s) continue;
          double lx = light->c.x - P.x, ly = light->c.y - P.y, lz = light->c.z - P.z;
          double distance = sqrt(lx * lx + ly * ly + lz * lz), lk = 1 / distance;
          vec L = { lx * lk, ly * lk, lz * lk };
          double cos = Nn.x * L.x + Nn.y * L.y + Nn.z * L.z;
          if (cos <= 0) continue;
          vec origin = { P.x + Nn.x * BIAS, P.y + Nn.y * BIAS, P.z + Nn.z * BIAS };
          double reach = distance - BIAS;
          int blocked = 0;
          for (int i = 0; i < N && !blocked; i++) {
            if (&spheres[i] == light) continue;
            if (hit(&spheres[i], origin, L, EPSILON) < reach) blocked = 1; /* every sphere here is opaque */
          }
          if (blocked) continue;
          out.x += light->emission.x * (s->color.x * cos);
          out.y += light->emission.y * (s->color.y * cos);
          out.z += light->emission.z * (s->color.z * cos);
        }
      }
      unsigned char *p = &frame[(y * W + x) * 4];
      p[0] = byte(out.x); p[1] = byte(out.y); p[2] = byte(out.z); p[3] = 255;
    }
  }
}

int main(int argc, char **argv) {
  int frames = argc > 1 ? atoi(argv[1]) : 1;
  add(0, 0, -10004, -20, 10000, (vec){ 0.2, 0.2, 0.2 }, 0);
  add(1, 0, 0, -20, 4, (vec){ 1, 0.32, 0.36 }, 0);
  add(2, 5, -1, -15, 2, (vec){ 0.9, 0.76, 0.46 }, 0);
  add(3, 5, 0, -25, 3, (vec){ 0.65, 0.77, 0.97 }, 0);
  add(4, -5.5, 0, -15, 3, (vec){ 0.9, 0.9, 0.9 }, 0);
  add(5, 0, 20, -30, 3, (vec){ 0, 0, 0 }, 1.2);
  add(6, 0, 10, 10, 3, (vec){ 0, 0, 0 }, 1);
  for (int f = 0; f < frames; f++) {
    struct timespec a, b;
    clock_gettime(CLOCK_MONOTONIC, &a);
    render();
    clock_gettime(CLOCK_MONOTONIC, &b);
    printf("%.3f\n", (b.tv_sec - a.tv_sec) * 1e3 + (b.tv_nsec - a.tv_nsec) / 1e6);
  }
  if (argc > 2) {
    FILE *out = fopen(argv[2], "wb");
    if (!out || fwrite(frame, 1, sizeof frame, out) != sizeof frame) return 1;
    fclose(out);
  }
  return 0;
}

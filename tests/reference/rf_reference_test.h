/* rf_reference_test.h: scenes, cameras and closed forms for the C tests of the reference
 * tracer. The optics here are written out independently of rf_optics.c (the code under
 * test uses that), so a shared mistake cannot make a test pass. */
#ifndef RF_REFERENCE_TEST_H
#define RF_REFERENCE_TEST_H

#include "rf_tracer.h"
#include "rf_vec3.h"

#include "rf_test.h"

#include <math.h>
#include <string.h>

#define RFT_PI 3.14159265358979323846
#define RFT_DEG (RFT_PI / 180.0)

/* A box as 6 faces x 4 vertices with flat normals (so interpolation returns the face
 * normal exactly), rotated by `rotation` (row-major 3x3, local -> world; NULL: axis-aligned)
 * about its centre. */
typedef struct rft_box
{
  float positions[72];
  float normals[72];
  unsigned triangles[36];
} rft_box;

static inline void rft_make_box(rft_box* box, const double centre[3], const double half[3],
  const double rotation[9])
{
  /* Face k: axis k/2, sign +1 for even k. Corners in counter-clockwise order seen from
   * outside. */
  const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  const double* turn = rotation ? rotation : identity;
  int face;
  for (face = 0; face < 6; ++face)
  {
    const int axis = face / 2;
    const double sign = (face % 2 == 0) ? 1.0 : -1.0;
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    const double cu[4] = { -1.0, 1.0, 1.0, -1.0 };
    const double cv[4] = { -1.0, -1.0, 1.0, 1.0 };
    int corner;
    for (corner = 0; corner < 4; ++corner)
    {
      double local[3];
      double n_local[3] = { 0.0, 0.0, 0.0 };
      int r;
      local[axis] = sign * half[axis];
      local[u] = cu[corner] * half[u] * sign;
      local[v] = cv[corner] * half[v];
      n_local[axis] = sign;
      for (r = 0; r < 3; ++r)
      {
        const double p =
          turn[3 * r + 0] * local[0] + turn[3 * r + 1] * local[1] + turn[3 * r + 2] * local[2];
        const double n = turn[3 * r + 0] * n_local[0] + turn[3 * r + 1] * n_local[1] +
          turn[3 * r + 2] * n_local[2];
        box->positions[3 * (4 * face + corner) + r] = (float)(centre[r] + p);
        box->normals[3 * (4 * face + corner) + r] = (float)n;
      }
    }
    box->triangles[6 * face + 0] = (unsigned)(4 * face + 0);
    box->triangles[6 * face + 1] = (unsigned)(4 * face + 1);
    box->triangles[6 * face + 2] = (unsigned)(4 * face + 2);
    box->triangles[6 * face + 3] = (unsigned)(4 * face + 0);
    box->triangles[6 * face + 4] = (unsigned)(4 * face + 2);
    box->triangles[6 * face + 5] = (unsigned)(4 * face + 3);
  }
}

static inline rf_mesh rft_box_mesh(const rft_box* box, double ior, int with_normals)
{
  rf_mesh mesh;
  memset(&mesh, 0, sizeof(mesh));
  mesh.positions = box->positions;
  mesh.normals = with_normals ? box->normals : NULL;
  mesh.vertex_count = 24;
  mesh.triangles = box->triangles;
  mesh.triangle_count = 12;
  mesh.ior = ior;
  return mesh;
}

/* Rotation about x (row-major). */
static inline void rft_rotation_x(double angle, double r[9])
{
  const double c = cos(angle);
  const double s = sin(angle);
  const double m[9] = { 1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c };
  memcpy(r, m, sizeof(m));
}

static inline void rft_identity4(double m[16])
{
  int i;
  for (i = 0; i < 16; ++i)
  {
    m[i] = (i % 5 == 0) ? 1.0 : 0.0;
  }
}

/* VTK's parallel projection (vtkPerspectiveTransform::Ortho through vtkCamera): half height
 * `scale`, aspect = width / height, clipping distances near < far in front of the eye. */
static inline void rft_ortho(double scale, double aspect, double near_d, double far_d,
  double m[16])
{
  rft_identity4(m);
  m[0] = 1.0 / (scale * aspect);
  m[5] = 1.0 / scale;
  m[10] = -2.0 / (far_d - near_d);
  m[11] = -(far_d + near_d) / (far_d - near_d);
}

/* A parallel camera on the +z axis at `eye_distance` from the origin, looking down -z with +y
 * up: VTK's projection of half height `scale` for a width x height image, clipping between
 * near_d and far_d. Tests that look from elsewhere replace `view` afterwards. */
static inline rf_camera rft_parallel_camera(double eye_distance, double scale, int width,
  int height, double near_d, double far_d)
{
  rf_camera camera;
  rft_identity4(camera.view);
  /* 0.0 - d rather than -d: an eye at the origin keeps a +0.0 entry, as a plain identity. */
  camera.view[11] = 0.0 - eye_distance;
  rft_ortho(scale, (double)width / height, near_d, far_d, camera.projection);
  camera.width = width;
  camera.height = height;
  return camera;
}

/* World -> view for an eye at `eye` looking along unit `forward` with `up`: rows right, up',
 * -forward; the view-space eye is the origin. */
static inline void rft_look_along(rf_vec3 eye, rf_vec3 forward, rf_vec3 up, double m[16])
{
  const rf_vec3 right = rf_vec3_normalize(rf_vec3_cross(forward, up));
  const rf_vec3 true_up = rf_vec3_cross(right, forward);
  const rf_vec3 back = rf_vec3_scale(forward, -1.0);
  const rf_vec3 rows[3] = { right, true_up, back };
  int r;
  rft_identity4(m);
  for (r = 0; r < 3; ++r)
  {
    m[4 * r + 0] = rows[r].x;
    m[4 * r + 1] = rows[r].y;
    m[4 * r + 2] = rows[r].z;
    m[4 * r + 3] = -rf_vec3_dot(rows[r], eye);
  }
}

/* The common start of a tracer test: one glass box with its face normals, the camera, default
 * options and an image of the camera's size (the test frees it: rf_trace_image_free). `glass`
 * points into `box`, so the scene is used where it was initialized, never copied. */
typedef struct rft_box_scene
{
  rft_box box;
  rf_mesh glass;
  rf_camera camera;
  rf_trace_options options;
  rf_trace_image image;
} rft_box_scene;

static inline void rft_box_scene_init(rft_box_scene* scene, const double centre[3],
  const double half[3], const double rotation[9], double ior, rf_camera camera)
{
  rft_make_box(&scene->box, centre, half, rotation);
  scene->glass = rft_box_mesh(&scene->box, ior, 1);
  scene->camera = camera;
  /* Checked here, so that every test built on a scene still asserts that its setup works. */
  CHECK(rf_trace_options_default(&scene->options) == RF_OK);
  CHECK(rf_trace_image_alloc(&scene->image, camera.width, camera.height) == RF_OK);
}

/* The scene traced as it stands: its glass alone, into its own image. */
static inline rf_status rft_box_scene_trace(rft_box_scene* scene)
{
  return rf_trace(&scene->glass, 1, &scene->camera, &scene->options, &scene->image);
}

/* The largest errors over the pixels of an image that a test compares with its closed form,
 * by kind; what a kind means (and its unit) is the test's to say. */
typedef struct rft_pixel_errors
{
  int checked;     /* pixels compared */
  int flags_wrong; /* pixels whose hit, bounce or TIR flags differ */
  double position; /* |P error| */
  double angle;    /* direction error, degrees */
  double length;   /* path length or shift error */
  double colour;   /* |colour error| per channel */
} rft_pixel_errors;

static inline rf_vec3 rft_to_view_point(const double m[16], rf_vec3 p)
{
  return rf_vec3_make(m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3],
    m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7], m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]);
}

static inline rf_vec3 rft_to_view_dir(const double m[16], rf_vec3 d)
{
  return rf_vec3_make(m[0] * d.x + m[1] * d.y + m[2] * d.z, m[4] * d.x + m[5] * d.y + m[6] * d.z,
    m[8] * d.x + m[9] * d.y + m[10] * d.z);
}

static inline rf_vec3 rft_load(const float* array, size_t index)
{
  return rf_vec3_make(array[3 * index], array[3 * index + 1], array[3 * index + 2]);
}

static inline double rft_distance(rf_vec3 a, rf_vec3 b)
{
  return rf_vec3_length(rf_vec3_sub(a, b));
}

/* Angle between two directions in degrees, accurate for small angles. */
static inline double rft_angle_deg(rf_vec3 a, rf_vec3 b)
{
  return atan2(rf_vec3_length(rf_vec3_cross(a, b)), rf_vec3_dot(a, b)) / RFT_DEG;
}

/* Snell's law written out: sin(theta_t) = n1 / n2 sin(theta_i). */
static inline double rft_snell(double theta_i, double n1, double n2)
{
  return asin(n1 / n2 * sin(theta_i));
}

/* Unpolarized Fresnel reflectance from the Fresnel equations in terms of the two angles
 * (Born & Wolf): rs = -sin(ti - tt)/sin(ti + tt), rp = tan(ti - tt)/tan(ti + tt). */
static inline double rft_fresnel(double theta_i, double n1, double n2)
{
  const double theta_t = rft_snell(theta_i, n1, n2);
  double rs;
  double rp;
  if (theta_i == 0.0)
  {
    const double r = (n1 - n2) / (n1 + n2);
    return r * r;
  }
  rs = -sin(theta_i - theta_t) / sin(theta_i + theta_t);
  rp = tan(theta_i - theta_t) / tan(theta_i + theta_t);
  return 0.5 * (rs * rs + rp * rp);
}

#endif /* RF_REFERENCE_TEST_H */

/* Unit tests of rf_optics (and the kernel's chord-symmetric normal) against closed forms
 * computed here by hand. */
#include "rf_optics.h"

#include "rf_kernel_optics.h"
#include "rf_test.h"

#include <math.h>

/* C99 has no M_PI. */
#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

/* A unit ray in the xz plane at angle theta from the normal (0, 0, 1),
 * travelling down (-z) toward the surface z = 0 and to the right (+x). */
static rf_vec3 incident_at(double theta)
{
  return rf_vec3_make(sin(theta), 0.0, -cos(theta));
}

static const rf_vec3 up = { 0.0, 0.0, 1.0 };

static void test_reflect(void)
{
  /* Mirror about z: (sin t, 0, -cos t) -> (sin t, 0, cos t). */
  const rf_vec3 r = rf_reflect(incident_at(30.0 * DEG), up);
  CHECK_NEAR(r.x, 0.5, 1e-15);
  CHECK_NEAR(r.y, 0.0, 1e-15);
  CHECK_NEAR(r.z, sqrt(3.0) / 2.0, 1e-15);
}

static void test_snell_normal_incidence(void)
{
  /* No tangential component: the ray goes straight through for any eta. */
  const rf_vec3 down = { 0.0, 0.0, -1.0 };
  rf_vec3 t = { 9.0, 9.0, 9.0 };
  CHECK(rf_refract(down, up, 1.0 / 1.5, &t) == RF_OK);
  CHECK_NEAR(t.x, 0.0, 1e-15);
  CHECK_NEAR(t.y, 0.0, 1e-15);
  CHECK_NEAR(t.z, -1.0, 1e-15);
  CHECK(rf_refract(down, up, 1.5, &t) == RF_OK);
  CHECK_NEAR(t.z, -1.0, 1e-15);
}

static void test_snell_30_degrees(void)
{
  /* Air (1) into glass (1.5) at 30 degrees: 1 sin 30 = 1.5 sin t2, so
   * sin t2 = 0.5 / 1.5 = 1/3 and cos t2 = sqrt(8/9) = 0.9428090415820634. */
  const double n1 = 1.0;
  const double n2 = 1.5;
  rf_vec3 t = { 0.0, 0.0, 0.0 };
  CHECK(rf_refract(incident_at(30.0 * DEG), up, n1 / n2, &t) == RF_OK);
  CHECK_NEAR(t.x, 1.0 / 3.0, 1e-14);
  CHECK_NEAR(t.y, 0.0, 1e-15);
  CHECK_NEAR(t.z, -sqrt(8.0 / 9.0), 1e-14);
  CHECK_NEAR(n1 * sin(30.0 * DEG), n2 * t.x, 1e-14); /* the sine law itself */
  CHECK_NEAR(rf_vec3_length(t), 1.0, 1e-14);

  /* A shading normal facing away from the viewer is flipped: same result. */
  {
    rf_vec3 flipped = { 0.0, 0.0, 0.0 };
    CHECK(rf_refract(incident_at(30.0 * DEG), rf_vec3_make(0.0, 0.0, -1.0), n1 / n2, &flipped) ==
      RF_OK);
    CHECK_NEAR(flipped.x, 1.0 / 3.0, 1e-14);
    CHECK_NEAR(flipped.z, -sqrt(8.0 / 9.0), 1e-14);
  }
  /* Glass back into air reverses the path: sin t = 1.5 (1/3) = 0.5. */
  CHECK(rf_refract(t, up, n2 / n1, &t) == RF_OK);
  CHECK_NEAR(t.x, 0.5, 1e-14);
  CHECK_NEAR(t.z, -sqrt(3.0) / 2.0, 1e-14);
}

static void test_critical_angle(void)
{
  /* Glass (1.5) to air (1): sin(theta_c) = 1/1.5, theta_c = 41.8103149 deg. */
  const double eta = 1.5;
  const double theta_c = asin(1.0 / 1.5);
  rf_vec3 t = { 0.0, 0.0, 0.0 };
  CHECK_NEAR(rf_critical_angle(eta), 0.72972765622696634, 1e-15);
  CHECK_NEAR(1.5 * sin(rf_critical_angle(eta)), 1.0, 1e-15);
  CHECK(rf_critical_angle(1.0) == -1.0);
  CHECK(rf_critical_angle(1.0 / 1.5) == -1.0);
  CHECK(rf_critical_angle(NAN) == -1.0);

  /* Just below: refracts, nearly grazing (sin t2 = 1.5 sin(theta) < 1). */
  CHECK(rf_refract(incident_at(theta_c - 1e-6), up, eta, &t) == RF_OK);
  CHECK_NEAR(t.x, 1.5 * sin(theta_c - 1e-6), 1e-12);
  CHECK(t.z < 0.0);

  /* Just above: total internal reflection, reflected direction returned. */
  CHECK(rf_refract(incident_at(theta_c + 1e-6), up, eta, &t) == RF_TIR);
  CHECK_NEAR(t.x, sin(theta_c + 1e-6), 1e-14);
  CHECK_NEAR(t.y, 0.0, 1e-15);
  CHECK_NEAR(t.z, cos(theta_c + 1e-6), 1e-14);

  /* The paper's clamp: the ray is tangent to the surface, in the plane of
   * incidence, continuing in the incident's tangential direction +x. */
  CHECK(rf_refract_clamped(incident_at(theta_c + 1e-6), up, eta, &t) == RF_TIR);
  CHECK_NEAR(rf_vec3_dot(t, up), 0.0, 1e-15);
  CHECK_NEAR(t.x, 1.0, 1e-15);
  CHECK_NEAR(t.y, 0.0, 1e-15);
  CHECK(rf_refract_clamped(incident_at(60.0 * DEG), up, eta, &t) == RF_TIR);
  CHECK_NEAR(t.x, 1.0, 1e-15);
  CHECK_NEAR(t.z, 0.0, 1e-15);
  /* An arbitrary plane of incidence: t stays in span(incident, normal). */
  {
    const rf_vec3 incident = rf_vec3_normalize(rf_vec3_make(0.6, 0.6, -0.2));
    const rf_vec3 plane_normal = rf_vec3_cross(incident, up);
    CHECK(rf_refract_clamped(incident, up, eta, &t) == RF_TIR);
    CHECK_NEAR(rf_vec3_dot(t, up), 0.0, 1e-15);
    CHECK_NEAR(rf_vec3_dot(t, plane_normal), 0.0, 1e-15);
    CHECK_NEAR(t.x, sqrt(0.5), 1e-15);
    CHECK_NEAR(t.y, sqrt(0.5), 1e-15);
  }
  /* Below the critical angle the clamped version is plain Snell. */
  CHECK(rf_refract_clamped(incident_at(30.0 * DEG), up, 1.0 / 1.5, &t) == RF_OK);
  CHECK_NEAR(t.x, 1.0 / 3.0, 1e-14);
}

static void test_refract_errors(void)
{
  const rf_vec3 down = { 0.0, 0.0, -1.0 };
  const rf_vec3 zero = { 0.0, 0.0, 0.0 };
  rf_vec3 t;
  CHECK(rf_refract(down, up, 1.5, NULL) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_refract_clamped(down, up, 1.5, NULL) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_refract(down, up, 0.0, &t) == RF_ERR_IOR_NOT_POSITIVE);
  CHECK(rf_refract(down, up, -1.0, &t) == RF_ERR_IOR_NOT_POSITIVE);
  CHECK(rf_refract(down, up, NAN, &t) == RF_ERR_NOT_FINITE);
  CHECK(rf_refract_clamped(down, up, INFINITY, &t) == RF_ERR_NOT_FINITE);
  CHECK(rf_refract(rf_vec3_make(NAN, 0.0, -1.0), up, 1.5, &t) == RF_ERR_NOT_FINITE);
  CHECK(rf_refract(down, rf_vec3_make(0.0, INFINITY, 1.0), 1.5, &t) == RF_ERR_NOT_FINITE);
  CHECK(rf_refract(zero, up, 1.5, &t) == RF_ERR_DEGENERATE_DIRECTION);
  CHECK(rf_refract(down, zero, 1.5, &t) == RF_ERR_DEGENERATE_DIRECTION);
}

/* Grazing so closely that the tangential part is 1e-160 long (its square is subnormal): under
 * the clamp policy the ray leaves along that part, still a unit vector (found by fuzzing: a
 * division by the inexact length gave |T| = 1.0000036). */
static void test_clamp_with_a_tiny_tangential_part(void)
{
  const rf_vec3 incident = rf_vec3_make(-1.0, 2.2250738585072014e-308, 0.0);
  const rf_vec3 normal = rf_vec3_make(5.5418492252184426e+156, -0.0013256275272755017, 1e-6);
  rf_vec3 t;
  CHECK(rf_refract_clamped(incident, normal, 5.5418492252184426e+156, &t) == RF_TIR);
  CHECK_NEAR(rf_vec3_length(t), 1.0, 1e-12);
  CHECK_NEAR(rf_vec3_dot(t, rf_vec3_normalize(normal)), 0.0, 1e-12);
}

/* Fresnel reflectances written out from the Fresnel equations with the
 * indices themselves, independent of the eta form used in rf_optics.c. */
static double hand_rs(double n1, double n2, double theta_i)
{
  const double sin_t = n1 * sin(theta_i) / n2;
  const double cos_t = sqrt(1.0 - sin_t * sin_t);
  return (n1 * cos(theta_i) - n2 * cos_t) / (n1 * cos(theta_i) + n2 * cos_t);
}

static double hand_rp(double n1, double n2, double theta_i)
{
  const double sin_t = n1 * sin(theta_i) / n2;
  const double cos_t = sqrt(1.0 - sin_t * sin_t);
  return (n2 * cos(theta_i) - n1 * cos_t) / (n2 * cos(theta_i) + n1 * cos_t);
}

static void test_fresnel_closed_forms(void)
{
  /* Normal incidence: ((n1 - n2) / (n1 + n2))^2 = (0.5 / 2.5)^2 = 0.04,
   * the same from either side. */
  CHECK_NEAR(rf_fresnel_dielectric(1.0, 1.0 / 1.5), 0.04, 1e-15);
  CHECK_NEAR(rf_fresnel_dielectric(1.0, 1.5), 0.04, 1e-15);
  CHECK_NEAR(rf_fresnel_dielectric(-1.0, 1.0 / 1.5), 0.04, 1e-15); /* |cos| */
  /* Water 1.33 -> air: (0.33 / 2.33)^2. */
  CHECK_NEAR(rf_fresnel_dielectric(1.0, 1.33), (0.33 / 2.33) * (0.33 / 2.33), 1e-15);
  /* Matched indices: nothing is reflected at any angle. */
  CHECK_NEAR(rf_fresnel_dielectric(0.3, 1.0), 0.0, 1e-15);

  /* Brewster air -> glass: tan(theta_B) = 1.5, cos(theta_B) = 1/sqrt(3.25),
   * theta_t = 90 deg - theta_B so n2 cos_t = 1.5 sin(theta_B) = 2.25/sqrt(3.25).
   * rs = (1 - 2.25) / (1 + 2.25) = -5/13 and rp = 0, so R = (25/169)/2
   * = 25/338 = 0.073964497... */
  {
    const double theta_b = rf_brewster_angle(1.0, 1.5);
    const double rs = hand_rs(1.0, 1.5, theta_b);
    CHECK_NEAR(theta_b, atan(1.5), 1e-15);
    CHECK_NEAR(cos(theta_b), 1.0 / sqrt(3.25), 1e-15);
    CHECK_NEAR(rs, -5.0 / 13.0, 1e-15);
    CHECK_NEAR(hand_rp(1.0, 1.5, theta_b), 0.0, 1e-15);
    CHECK_NEAR(rf_fresnel_dielectric(cos(theta_b), 1.0 / 1.5), 25.0 / 338.0, 1e-15);
    CHECK_NEAR(rf_fresnel_dielectric(cos(theta_b), 1.0 / 1.5), rs * rs / 2.0, 1e-15);
  }
  /* Brewster glass -> air: tan(theta_B) = 1/1.5, rs = +5/13, same R. */
  {
    const double theta_b = rf_brewster_angle(1.5, 1.0);
    CHECK_NEAR(theta_b, atan(1.0 / 1.5), 1e-15);
    CHECK_NEAR(rf_fresnel_dielectric(cos(theta_b), 1.5), 25.0 / 338.0, 1e-15);
  }
  CHECK(rf_brewster_angle(0.0, 1.5) == -1.0);
  CHECK(rf_brewster_angle(1.0, NAN) == -1.0);

  /* Away from the special angles the result is (rs^2 + rp^2) / 2. */
  {
    const double theta = 50.0 * DEG;
    const double rs = hand_rs(1.0, 1.5, theta);
    const double rp = hand_rp(1.0, 1.5, theta);
    CHECK_NEAR(rf_fresnel_dielectric(cos(theta), 1.0 / 1.5), 0.5 * (rs * rs + rp * rp), 1e-15);
  }
  /* Grazing from air: everything reflects. */
  CHECK_NEAR(rf_fresnel_dielectric(0.0, 1.0 / 1.5), 1.0, 1e-15);
}

static void test_fresnel_tir_and_sweep(void)
{
  const double theta_c = asin(1.0 / 1.5);
  const double etas[] = { 1.0 / 1.5, 1.5, 1.0 / 1.33, 1.33, 0.75, 1.0 };
  int e;
  int i;
  /* Beyond the critical angle: total reflection. */
  CHECK(rf_fresnel_dielectric(cos(theta_c + 1e-6), 1.5) == 1.0);
  CHECK(rf_fresnel_dielectric(cos(60.0 * DEG), 1.5) == 1.0);
  CHECK(rf_fresnel_dielectric(0.0, 1.5) == 1.0);
  /* Continuity at the critical angle: R -> 1 from below (as a square root
   * of the distance, so 1e-10 rad below leaves R within ~1e-4 of 1). */
  CHECK(rf_fresnel_dielectric(cos(theta_c - 1e-10), 1.5) > 0.999);
  CHECK(rf_fresnel_dielectric(cos(theta_c - 1e-10), 1.5) <= 1.0);
  CHECK(rf_fresnel_dielectric(cos(theta_c - 1e-4), 1.5) > 0.9);

  /* Energy conservation: R in [0, 1]. The unpolarized R is also
   * non-decreasing in the angle (rp^2 dips to 0 at Brewster's angle, but rs^2
   * grows faster), from either side of the interface. */
  for (e = 0; e < (int)(sizeof(etas) / sizeof(etas[0])); ++e)
  {
    double previous = -1.0;
    for (i = 0; i <= 900; ++i)
    {
      const double theta = i * 0.1 * DEG;
      const double r = rf_fresnel_dielectric(cos(theta), etas[e]);
      const double schlick = rf_fresnel_schlick(cos(theta), etas[e]);
      CHECK(r >= 0.0 && r <= 1.0);
      CHECK(schlick >= 0.0 && schlick <= 1.0);
      CHECK(r >= previous - 1e-15);
      previous = r;
    }
  }
}

static void test_schlick(void)
{
  const double theta_c = asin(1.0 / 1.5);
  int i;
  /* R0 at normal incidence, 1 at grazing, 1 under TIR. */
  CHECK_NEAR(rf_fresnel_schlick(1.0, 1.0 / 1.5), 0.04, 1e-15);
  CHECK_NEAR(rf_fresnel_schlick(1.0, 1.5), 0.04, 1e-15);
  CHECK_NEAR(rf_fresnel_schlick(0.0, 1.0 / 1.5), 1.0, 1e-15);
  CHECK(rf_fresnel_schlick(cos(theta_c + 1e-6), 1.5) == 1.0);
  /* R0 + (1 - R0)(1 - cos 60)^5 = 0.04 + 0.96 / 32 = 0.07. */
  CHECK_NEAR(rf_fresnel_schlick(0.5, 1.0 / 1.5), 0.07, 1e-15);
  /* Leaving glass (eta = 1.5) the transmitted cosine is used: at 30 deg
   * sin t = 1.5 * 0.5 = 0.75, cos t = sqrt(1 - 0.5625) = sqrt(0.4375). */
  CHECK_NEAR(rf_fresnel_schlick(cos(30.0 * DEG), 1.5),
    0.04 + 0.96 * pow(1.0 - sqrt(0.4375), 5.0), 1e-15);
  /* A usable approximation of the exact curve for glass seen from air. */
  for (i = 0; i <= 90; ++i)
  {
    const double c = cos(i * DEG);
    CHECK(fabs(rf_fresnel_schlick(c, 1.0 / 1.5) - rf_fresnel_dielectric(c, 1.0 / 1.5)) < 0.05);
  }
  CHECK(isnan(rf_fresnel_schlick(0.5, 0.0)));
  CHECK(isnan(rf_fresnel_dielectric(0.5, -1.0)));
  CHECK(isnan(rf_fresnel_dielectric(NAN, 1.5)));
}

/* Inside a sphere a reflected chord meets its far end at the angle it left its near end:
 * from an estimate of the far end's normal turned within the plane of the chord (as a
 * texel's normal near the rim is), the chord-symmetric normal is the sphere's, exactly. */
static void test_chord_symmetric_normal_in_a_sphere(void)
{
  const rf_vec3 centre = { 0.3, -0.2, -5.0 };
  const double radius = 1.6;
  int i;
  for (i = 0; i < 40; ++i)
  {
    /* A point on the sphere and a direction inside at angle theta to its inward normal. */
    const double phi = 0.37 * i;
    const double theta = (0.5 + 88.0 * i / 39.0) * DEG;
    const rf_vec3 n1 = rf_vec3_make(cos(phi) * 0.8, sin(phi) * 0.8, 0.6);
    const rf_vec3 p1 = rf_vec3_add(centre, rf_vec3_scale(n1, radius));
    const rf_vec3 side = rf_vec3_normalize(rf_vec3_cross(n1, rf_vec3_make(0.0, 0.0, 1.0)));
    const rf_vec3 chord = rf_vec3_normalize(
      rf_vec3_add(rf_vec3_scale(n1, -cos(theta)), rf_vec3_scale(side, sin(theta))));
    const double cos_exit = -rf_vec3_dot(chord, n1);
    /* The chord's far end: t = -2 dot(p1 - c, chord). */
    const double t = -2.0 * rf_vec3_dot(rf_vec3_sub(p1, centre), chord);
    const rf_vec3 p2 = rf_vec3_add(p1, rf_vec3_scale(chord, t));
    const rf_vec3 n2 = rf_vec3_scale(rf_vec3_sub(p2, centre), 1.0 / radius);
    /* The estimate: the true normal turned toward or away from the chord by up to 25 degrees
     * (less than the chord's angle, so it stays on its side of the chord). */
    const double turn = (i % 2 ? 1.0 : -1.0) * fmin(25.0 * DEG, 0.9 * theta) * (i % 5) / 4.0;
    const rf_vec3 along = rf_vec3_normalize(
      rf_vec3_sub(chord, rf_vec3_scale(n2, rf_vec3_dot(chord, n2))));
    const rf_vec3 estimated =
      rf_vec3_add(rf_vec3_scale(n2, cos(turn)), rf_vec3_scale(along, sin(turn)));
    const rf_vec3 n = rfk_chord_symmetric_normal(chord, estimated, cos_exit);
    CHECK_NEAR(rf_vec3_dot(chord, n2), cos_exit, 1e-12);
    CHECK_NEAR(n.x, n2.x, 1e-9);
    CHECK_NEAR(n.y, n2.y, 1e-9);
    CHECK_NEAR(n.z, n2.z, 1e-9);
  }
  /* An estimate along the chord has no plane: the chord itself. */
  {
    const rf_vec3 chord = { 0.0, 0.6, 0.8 };
    const rf_vec3 n = rfk_chord_symmetric_normal(chord, chord, 0.5);
    CHECK(n.x == chord.x && n.y == chord.y && n.z == chord.z);
  }
  /* A cosine beyond 1 (rounding) stays a unit normal along the chord. */
  {
    const rf_vec3 n = rfk_chord_symmetric_normal(up, rf_vec3_make(1.0, 0.0, 0.0), 1.0 + 1e-12);
    CHECK_NEAR(rf_vec3_length(n), 1.0, 1e-15);
    CHECK_NEAR(n.z, 1.0, 1e-15);
  }
}

int main(void)
{
  test_reflect();
  test_snell_normal_incidence();
  test_snell_30_degrees();
  test_critical_angle();
  test_refract_errors();
  test_clamp_with_a_tiny_tangential_part();
  test_fresnel_closed_forms();
  test_fresnel_tir_and_sweep();
  test_schlick();
  test_chord_symmetric_normal_in_a_sphere();
  return RF_TEST_SUMMARY();
}

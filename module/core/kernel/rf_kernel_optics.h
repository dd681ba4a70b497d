/* rf_kernel_optics.h (kernel dialect, C and GLSL): Snell's law with the TIR policy and the
 * dielectric Fresnel terms at one interface. One source for rf_optics.c (which validates and
 * normalizes the inputs first) and the shaders.
 * Conventions of GLSL refract(): unit directions; eta = n_incident / n_transmitted. */
#ifndef RF_KERNEL_OPTICS_H
#define RF_KERNEL_OPTICS_H

#ifndef RF_GLSL
#include "rf_kernel_prelude.h"
#endif

/* What happens beyond the critical angle. CLAMP is the paper's choice (section 5, after Wyman
 * 2005): the transmission angle is set to the critical angle, so the ray leaves tangent to the
 * surface. REFLECT follows the light by one mirror reflection. */
#define RF_TIR_POLICY_REFLECT 0
#define RF_TIR_POLICY_CLAMP 1

/* Return values of rfk_refract. */
#define RF_REFRACTED 0
#define RF_TOTAL_INTERNAL_REFLECTION 1

/* cos^2(theta_t) = 1 - sin^2(theta_t), with Snell's law n_i sin(theta_i) = n_t sin(theta_t):
 * sin^2(theta_t) = eta^2 sin^2(theta_i). Negative means TIR. At normal incidence every index
 * transmits: eta^2 may overflow, and inf * 0 would be NaN. */
RF_KERNEL rf_float rfk_transmitted_cos_squared(rf_float sin2Incident, rf_float eta)
{
  return sin2Incident > 0.0 ? 1.0 - eta * eta * sin2Incident : 1.0;
}

/* The normal turned against the incident ray. Interpolated (shading) normals near silhouettes
 * can face slightly away from the viewer although the face does not; refracting at the
 * interface the ray actually crosses needs them flipped. */
RF_KERNEL rf_float3 rfk_facing_normal(rf_float3 incident, rf_float3 normal)
{
  return rf_dot3(incident, normal) > 0.0 ? rf_neg3(normal) : normal;
}

/* The part of the incident direction along the surface, I - dot(I, N) N (sin(theta_i) long).
 * Refracting from it as eta T - sqrt(k) N avoids refract()'s eta I - (eta dot(N, I) + sqrt(k)) N,
 * which cancels to rounding noise for large eta: at eta = 1000 a float loses 6% of the
 * tangential part. Its squared length is also a better sin^2 than 1 - cos^2 near normal
 * incidence. */
RF_KERNEL rf_float3 rfk_tangential_part(rf_float3 incident, rf_float3 facingNormal)
{
  return rf_sub3(incident, rf_scale3(facingNormal, rf_dot3(incident, facingNormal)));
}

/* Snell's law (as GLSL refract()) with the TIR policy. `incident` and `normal`
 * are unit; the normal may face either way (rfk_facing_normal). Writes the unit transmitted
 * direction and returns RF_REFRACTED, or under TIR the policy's direction and returns
 * RF_TOTAL_INTERNAL_REFLECTION. */
RF_KERNEL int rfk_refract(rf_float3 incident, rf_float3 normal, rf_float eta, int tirPolicy,
  RF_OUT(rf_float3) transmitted)
{
  /* Equal indices are no interface: the ray goes straight on, exactly (the formula below only
   * up to rounding, which near grazing incidence is not small). */
  if (eta == 1.0)
  {
    RF_DEREF(transmitted) = incident;
    return RF_REFRACTED;
  }
  rf_float3 facing = rfk_facing_normal(incident, normal);
  rf_float3 tangent = rfk_tangential_part(incident, facing);
  rf_float k = rfk_transmitted_cos_squared(rf_dot3(tangent, tangent), eta);
  if (k < 0.0)
  {
    if (tirPolicy == RF_TIR_POLICY_CLAMP)
    {
      /* At 90 degrees the transmitted ray grazes the surface along the tangential part (in the
       * plane of incidence). TIR needs sin(theta_i) > 1/eta > 0, so the part vanishes only
       * through rounding: then the ray goes on unbent. rf_normalize3, not a division by the
       * length: in C a part of 1e-160 has a subnormal square and an inexact length (found by
       * fuzzing: |T| = 1.0000036), which rf_vec3_normalize avoids. */
      RF_DEREF(transmitted) = rf_length3(tangent) > 0.0 ? rf_normalize3(tangent) : incident;
    }
    else
    {
      RF_DEREF(transmitted) = rf_normalize3(rf_reflect3(incident, facing));
    }
    return RF_TOTAL_INTERNAL_REFLECTION;
  }
  /* Unit for unit inputs; normalizing only removes rounding. Without TIR eta |T| <= 1, so
   * nothing overflows. */
  RF_DEREF(transmitted) =
    rf_normalize3(rf_sub3(rf_scale3(tangent, eta), rf_scale3(facing, rf_sqrt(k))));
  return RF_REFRACTED;
}

/* Exact unpolarized dielectric Fresnel reflectance (rs^2 + rp^2) / 2. cosIncident is
 * |dot(I, N)| (its absolute value is taken, and clamped to 1); 1 under TIR. */
RF_KERNEL rf_float rfk_fresnel_dielectric(rf_float cosIncident, rf_float eta)
{
  /* Equal indices reflect nothing at any angle; at grazing incidence 1 - (1 - c^2) rounds to 0
   * and the formula below would report total reflection. */
  if (eta == 1.0)
  {
    return 0.0;
  }
  rf_float c = rf_min(rf_abs(cosIncident), 1.0);
  rf_float cos2t = rfk_transmitted_cos_squared(1.0 - c * c, eta);
  if (cos2t <= 0.0)
  {
    return 1.0; /* at and beyond the critical angle rs = rp = 1 */
  }
  rf_float cost = rf_sqrt(cos2t);
  /* The Fresnel equations divided through by n_t:
   * rs = (n_i cos_i - n_t cos_t) / (n_i cos_i + n_t cos_t),
   * rp = (n_t cos_i - n_i cos_t) / (n_t cos_i + n_i cos_t); rp vanishes at Brewster's angle. */
  rf_float rs = (eta * c - cost) / (eta * c + cost);
  rf_float rp = (c - eta * cost) / (c + eta * cost);
  return 0.5 * (rs * rs + rp * rp);
}

/* Schlick's approximation R0 + (1 - R0)(1 - cos)^5, for comparison. Leaving the denser medium
 * (eta > 1) it uses the transmitted cosine: Schlick's form is accurate only on the side of the
 * smaller index. 1 under TIR. */
RF_KERNEL rf_float rfk_fresnel_schlick(rf_float cosIncident, rf_float eta)
{
  if (eta == 1.0)
  {
    return 0.0; /* no interface (the formula would give (1 - cos)^5) */
  }
  rf_float c = rf_min(rf_abs(cosIncident), 1.0);
  rf_float r0 = (eta - 1.0) / (eta + 1.0); /* (n_i - n_t) / (n_i + n_t) */
  r0 = r0 * r0;
  rf_float cosine = c;
  if (eta > 1.0)
  {
    rf_float cos2t = rfk_transmitted_cos_squared(1.0 - c * c, eta);
    if (cos2t <= 0.0)
    {
      return 1.0;
    }
    cosine = rf_sqrt(cos2t);
  }
  rf_float m = 1.0 - cosine;
  return r0 + (1.0 - r0) * m * m * m * m * m;
}

/* The outward normal at the far end of a chord inside a convex glass, from an estimate of it:
 * inside a sphere a chord meets the surface at both ends at one angle, so the normal is turned
 * in the plane of the chord (unit) and the estimate until it meets the chord at cosExit, the
 * cosine at the interface the chord began from. Used where the estimate is a texel's one chord
 * on, which near a silhouette is off by many degrees: enough to reflect totally (and look
 * inwards) a chord that a sphere lets out. Only the estimate's plane (its side of the chord) is
 * kept; an estimate along the chord gives the chord. */
RF_KERNEL rf_float3 rfk_chord_symmetric_normal(rf_float3 chord, rf_float3 estimated,
  rf_float cosExit)
{
  rf_float3 across = rf_sub3(estimated, rf_scale3(chord, rf_dot3(estimated, chord)));
  rf_float acrossLength = rf_length3(across);
  if (!(acrossLength > 1e-4))
  {
    return chord;
  }
  rf_float c = rf_min(rf_abs(cosExit), 1.0);
  rf_float sinExit = rf_sqrt(rf_max(1.0 - c * c, 0.0));
  return rf_add3(rf_scale3(chord, c), rf_scale3(across, sinExit / acrossLength));
}

#endif /* RF_KERNEL_OPTICS_H */

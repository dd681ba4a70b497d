/* rf_optics.h: reflection, refraction and Fresnel terms at one interface.
 *
 * Conventions are those of GLSL so the C core and the shaders agree:
 *  - `incident` is the unit direction of travel of the ray;
 *  - `normal` is unit and faces against the incident ray, i.e.
 *    dot(incident, normal) <= 0;
 *  - `eta` = n_incident_side / n_transmitted_side, exactly the third argument
 *    of GLSL refract(); eta > 1 leaves a denser medium and can give TIR. */
#ifndef RF_OPTICS_H
#define RF_OPTICS_H

#include "rf_validate.h"
#include "rf_vec3.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Mirror direction, as GLSL reflect(): incident - 2 dot(normal, incident) normal. */
rf_vec3 rf_reflect(rf_vec3 incident, rf_vec3 normal);

/* Snell's law as GLSL refract(). On success *transmitted is the unit
 * transmitted direction and RF_OK is returned. Under total internal
 * reflection RF_TIR is returned and *transmitted is the reflected direction,
 * so a caller can keep following the light. A normal facing the same way as
 * the incident ray is flipped first (see rf_optics.c).
 * Errors: RF_ERR_NULL_ARGUMENT, RF_ERR_NOT_FINITE, RF_ERR_IOR_NOT_POSITIVE
 * (eta), RF_ERR_DEGENERATE_DIRECTION (zero incident or normal). */
rf_status rf_refract(rf_vec3 incident, rf_vec3 normal, double eta, rf_vec3* transmitted);

/* The paper's TIR policy (section 5, after Wyman 2005): when the transmission
 * angle would exceed the critical angle it is set to the critical angle, so
 * the refracted ray is tangent to the surface. Returns RF_TIR with that
 * tangent direction (unit, in the plane of incidence, perpendicular to the
 * normal, pointing along the incident ray's tangential motion), RF_OK with
 * the ordinary refracted direction otherwise. Errors as rf_refract. */
rf_status rf_refract_clamped(rf_vec3 incident, rf_vec3 normal, double eta, rf_vec3* transmitted);

/* Critical angle asin(1/eta) in radians when eta > 1; -1.0 when there is no
 * critical angle (eta <= 1) or eta is not finite. */
double rf_critical_angle(double eta);

/* Brewster's angle atan(n_transmitted / n_incident) in radians, where the
 * reflected light is purely s-polarized; -1.0 for non-positive or non-finite
 * indices. */
double rf_brewster_angle(double n_incident, double n_transmitted);

/* Exact unpolarized dielectric Fresnel reflectance (rs^2 + rp^2) / 2.
 * cos_incident = |dot(incident, normal)|, clamped to [0, 1]; eta as above.
 * Returns 1.0 under TIR and NaN for a NaN cosine or an invalid eta. */
double rf_fresnel_dielectric(double cos_incident, double eta);

/* Schlick's approximation R0 + (1 - R0)(1 - cos)^5, for comparison. When
 * leaving the denser medium (eta > 1) the transmitted cosine is used, as
 * Schlick's form is only accurate on the side of the smaller index; returns
 * 1.0 under TIR and NaN for a NaN cosine or an invalid eta. */
double rf_fresnel_schlick(double cos_incident, double eta);

#ifdef __cplusplus
}
#endif

#endif /* RF_OPTICS_H */

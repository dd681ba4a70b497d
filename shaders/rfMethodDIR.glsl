// DIR, Oliveira & Brauwers 2007 (sections 3.2-3.3): the exit point of the refracted ray T1 is
// found by the perspective-correct conservative binary search (algorithm 2) of the segment
// between the min/max back depths (eq. 3-10) against the captured back surface
// (rfBackSurface.glsl), refined by one secant step.
// Defines: RF_DEPTH_RANGE_BOUNDS, RF_ADAPTIVE_SEARCH, RF_SECANT_REFINE, RF_MAX_SEARCH_STEPS.
uniform int rfSearchSteps;
#ifdef RF_DEPTH_RANGE_BOUNDS
uniform vec2 rfDepthRangeBounds;
#else
uniform sampler2D rfDepthRangeTex;
#endif

// eq. 9: texture-space parameter of the point of depth z on the segment S-E; twin of rf_dir_alpha.
float rf_dir_alpha(float k1, float k2, float z)
{
  return (1.0 / z - k1) * k2;
}

vec2 rfDepthRange()
{
#ifdef RF_DEPTH_RANGE_BOUNDS
  return rfDepthRangeBounds;
#else
  return texelFetch(rfDepthRangeTex, ivec2(0, 0), 0).rg;
#endif
}

// Conservative binary search (algorithm 2) of T1 against the captured back depths; twin of
// rf_dir_cbs. The search starts at the entry point when it lies beyond Zmin (the part of the
// segment before P1 cannot hold the exit), which also keeps the start texel valid.
bool rf_dir_cbs(vec3 P1, vec3 T1, vec2 depthRange, out vec3 P2, out vec2 tc)
{
  P2 = P1;
  tc = rfProjectToTexture(P1);
  if (!(depthRange.x <= depthRange.y))
  {
    return false; // no back surface captured
  }
  // The segment as parameters along the unit T1. Eq. 3-4 put S and E on the planes Zmin and
  // Zmax; as T1.z -> 0 they go to infinity (and k2 of eq. 9 loses its meaning), so E is
  // clipped where the ray leaves the frustum, and a ray parallel to the image plane (or
  // turned toward the eye) is searched sideways from P1 at its own depth: the same segment
  // the clipped eq. 3-4 tend to, so nothing jumps at the threshold.
  float tFar = rfFrustumExit(P1, T1, false);
  float tS = 0.0;
  float tE = tFar;
  if (T1.z < -1e-6)
  {
    tS = max((-depthRange.x - P1.z) / T1.z, 0.0); // eq. 3; from P1 when P1 lies beyond Zmin
    tE = min((-depthRange.y - P1.z) / T1.z, tFar); // eq. 4
  }
  if (!(tE < 1e20))
  {
    return true; // no frustum plane ahead (rounding): the exit behind the entry point
  }
  // S must lie on the glass's back-surface footprint for the search to start there: where it
  // does not (outside the silhouette or the image) start from P1, which always does.
  vec3 S = P1 + tS * T1;
  if (tS > 0.0 && !(tS < tE && rfStoredDepth(rfProjectToTexture(S)) > 0.0))
  {
    tS = 0.0;
    S = P1;
  }
  // Zmin = Zmax (a flat back facing the camera, a single back texel), or P1 at or beyond Zmax:
  // the segment is (nearly) a point and S.z - E.z in k2 (eq. 9) tends to 0. The exit is S;
  // below a relative length of 1e-6 the search could not move it in float anyway.
  if (!(tE - tS > 1e-6 * length(S)))
  {
    P2 = S;
    tc = rfProjectToTexture(S);
    return true;
  }
  vec3 E = P1 + tE * T1;
  // Eq. 9 maps depth to the texture parameter; when the segment's depths (nearly) agree the
  // projection along it is affine and the parameter is the step fraction itself (also under a
  // parallel projection).
  bool rfAffine = rfParallel == 1 || S.z - E.z < 1e-4 * abs(S.z);
  float k1 = 1.0 / S.z;                                   // eq. 9
  float k2 = rfAffine ? 0.0 : S.z * E.z / (S.z - E.z);
  float beta = 0.0;
  float dbeta = 1.0;
  vec2 ts = rfProjectToTexture(S);
  vec2 dt = rfProjectToTexture(E) - ts;
  vec3 dv = E - S;
  P2 = S;
  int steps = rfSearchSteps;
#ifdef RF_ADAPTIVE_SEARCH
  // No more halvings than it takes to bring the bracket under half a texel of the segment's
  // projection (a coarser bracket picks the neighbouring texel's normal).
  float texels = length(dt * rfViewport.zw);
  steps = min(steps, int(ceil(log2(max(2.0 * texels, 1.0)))));
#endif
  // A loop bound known only at run time: with a constant bound (and a break) llvmpipe unrolls
  // all RF_MAX_SEARCH_STEPS iterations and pays for every texture fetch whatever the steps.
  steps = min(steps, RF_MAX_SEARCH_STEPS);
  for (int i = 0; i < steps; ++i)
  {
    dv *= 0.5;
    dbeta *= 0.5;
    float z = P2.z + dv.z;
    float alpha = rfAffine ? beta + dbeta : rf_dir_alpha(k1, k2, z);
    if (-z < rfStoredDepth(ts + alpha * dt)) // eq. 10; empty texels hold 0 and stop the advance
    {
      P2 += dv;
      beta += dbeta;
    }
  }
  tc = rfProjectToTexture(P2);
#ifdef RF_SECANT_REFINE
  // Beyond the paper: one secant step inside the final bracket [P2, P2 + dv] (relief
  // mapping's linear refinement); twin of rf_dir_secant_refine. Only across a valid far
  // texel (a crossing, not a silhouette), and only onto a valid texel (still conservative).
  if (steps > 0 && beta + dbeta <= 1.0)
  {
    vec3 farEnd = P2 + dv;
    float farAlpha = rfAffine ? beta + dbeta : rf_dir_alpha(k1, k2, farEnd.z);
    float farStored = rfStoredDepth(ts + farAlpha * dt);
    float nearGap = rfStoredDepth(tc) + P2.z;
    float farGap = farStored + farEnd.z;
    if (farStored > 0.0 && nearGap > 0.0 && farGap < 0.0)
    {
      vec3 refined = P2 + (nearGap / (nearGap - farGap)) * dv;
      vec2 refinedTC = rfProjectToTexture(refined);
      if (rfStoredDepth(refinedTC) > 0.0)
      {
        P2 = refined;
        tc = refinedTC;
      }
    }
  }
#endif
  return true;
}

bool rfFindExit(vec3 P1, vec3 V, vec3 N1, vec3 T1, float etaIn, out vec3 P2, out vec3 N2)
{
  vec2 tc;
  N2 = vec3(0.0);
  return rf_dir_cbs(P1, T1, rfDepthRange(), P2, tc) && rfBackNormalAt(tc, P1, N2);
}

// ISR, Wyman 2005 (eq. 1-2): the exit point at the estimated distance along T1, from d_V
// (along the view ray to the captured back depth) and d_N (per vertex, along the inward
// normal, in the G-buffer's auxiliary target), then the captured back normal there.
uniform sampler2D rfFrontAux;

// Wyman's estimate (eq. 1-2): d = (theta_t/theta_i) d_V + (1 - theta_t/theta_i) d_N, d_V
// along the view ray to the captured back depth, d_N per vertex along the inward normal.
float rfISRDistance(vec3 P1, vec3 V, vec3 N1, vec3 T1, float eta)
{
  float backDepth = rfStoredDepth(rfProjectToTexture(P1));
  float dV = backDepth > 0.0 ? max(backDepth + P1.z, 0.0) / max(-V.z, 1e-6) : 0.0;
  float thetaI = acos(clamp(-dot(V, N1), -1.0, 1.0));
  float thetaT = acos(clamp(-dot(T1, N1), -1.0, 1.0));
  // At normal incidence theta_t/theta_i tends to sin(theta_t)/sin(theta_i) = eta.
  float ratio = thetaI > 1e-4 ? thetaT / thetaI : eta;
  // d_N per pixel from the G-buffer (the geometry stage scales it with the actor; < 0: none).
  float dNStored = texelFetch(rfFrontAux, rfPixel, 0).r;
  float dN = dNStored >= 0.0 ? dNStored : dV;
  return ratio * dV + (1.0 - ratio) * dN;
}

bool rfFindExit(vec3 P1, vec3 V, vec3 N1, vec3 T1, float etaIn, out vec3 P2, out vec3 N2)
{
  P2 = P1 + rfISRDistance(P1, V, N1, T1, etaIn) * T1;
  N2 = vec3(0.0);
  return rfBackNormalAt(rfProjectToTexture(P2), P1, N2);
}

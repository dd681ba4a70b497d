// ISR, Wyman 2005 (eq. 1-2): the exit point at the estimated distance along T1, from d_V
// (along the view ray to the captured back depth) and d_N (per vertex, along the inward
// normal, in the G-buffer's auxiliary target), then the captured back normal there.
uniform sampler2D rfFrontAux;

// Wyman's estimate (eq. 1-2) from the kernel: d_V along the view ray to the captured back
// depth, d_N per pixel from the G-buffer (scaled with the actor; < 0: none, d_N = d_V).
float rfISRDistance(vec3 P1, vec3 V, vec3 N1, vec3 T1, float eta)
{
  float dV = rfk_isr_view_distance(rfStoredDepth(rfProjectToTexture(P1)), P1, V);
  float dNStored = texelFetch(rfFrontAux, rfPixel, 0).r;
  return rfk_isr_distance(dV, dNStored >= 0.0 ? dNStored : dV, V, N1, T1, eta);
}

bool rfFindExit(vec3 P1, vec3 V, vec3 N1, vec3 T1, float etaIn, out vec3 P2, out vec3 N2)
{
  P2 = P1 + rfISRDistance(P1, V, N1, T1, etaIn) * T1;
  N2 = vec3(0.0);
  return rfBackNormalAt(rfProjectToTexture(P2), P1, N2);
}

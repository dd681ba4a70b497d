// DIR pass 1 (Oliveira & Brauwers 2007, section 3.1): capture the back surface.
// Drawn with GL_GREATER and depth cleared to 0, so the furthest surface of the glass wins
// whatever the mesh's winding; empty texels keep 0, which is what the search tests against.
// With RF_BACK_NEAREST (beyond the paper) the nearest back-facing surface is kept instead
// (GL_LESS, front faces discarded by winding, flipped for meshes wound inward): on shapes of
// several parts it is the surface the refracted ray leaves through far more often.
// Inputs: rfP (view-space position), rfN (view-space shading normal).
#ifdef RF_BACK_NEAREST
    if (gl_FrontFacing == (rfWindingSign > 0))
    {
      discard;
    }
#endif
    vec3 rfOutward = dot(rfN, rfViewDirection(rfP)) < 0.0 ? -rfN : rfN;
    gl_FragData[0] = vec4(rfOutward, 1.0);
    gl_FragData[1] = vec4(-rfP.z, 0.0, 0.0, 1.0);

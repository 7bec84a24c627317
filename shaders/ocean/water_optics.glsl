// Light in a water column over a sea floor (seed 001, Baboud & Decoret 2006 §4.1, with the
// shallow-water reflectance of Maritorena, Morel & Gentili 1994). Written in the GLSL/C++
// subset (common/types.glsl): compiled as C++ in double by src/ocean/WaterOptics.cpp, whose CPU
// tests check it against the formulas; the shaders (ocean/water_volume.glsl, terrain/shallow.glsl)
// use the same code in float.
//
// Units: attenuation coefficients K per RGB channel in 1/m (diffuse attenuation at 600, 550 and
// 450 nm, Jerlov 1976 Table XXVII's water types: ocean::jerlovWater); paths and depths in m; irradiances in the renderer's units (the
// Sun's irradiance at the top of the atmosphere); reflectances in 1/sr (radiance per unit
// irradiance), the unit of uSeaColor.

// Refractive index of sea water (visible light, ~1.34).
const Number WATER_INDEX = 1.34;
// Radiance leaving the water per unit upwelling radiance just below the surface: the Fresnel
// transmission over the n² spreading of the beam, (1 - rho) / n² ~ 0.54 (Lee et al. 1998, Eq. 4,
// R_rs ~ 0.52-0.54 r_rs for the small reflectances of water).
const Number WATER_LEAVING_FACTOR = 0.54;

// Eq. 3, Baboud & Decoret 2006: alpha(d) = exp(-a d) per channel, the fraction of light left
// after a path of `pathM` metres through water of attenuation `attenuationPerM`.
vec3 waterTransmittance(vec3 attenuationPerM, Number pathM) {
  return exp(-attenuationPerM * max(pathM, Number(0.0)));
}

// Eq. 6, Baboud & Decoret 2006: d_max = -log(epsilon) / min(a), the path beyond which every
// channel keeps less than `epsilon` of the light (the march stops there), m.
Number waterMaxPathM(vec3 attenuationPerM, Number epsilon) {
  Number k = min(attenuationPerM.x, min(attenuationPerM.y, attenuationPerM.z));
  return -log(epsilon) / max(k, Number(1e-6));
}

// Cosine of a ray's zenith angle under a flat surface from its cosine `cosAir` above it
// (Snell: sin t = sin i / n), in (0, 1].
Number waterRefractedCosine(Number cosAir) {
  Number s = (1.0 - clamp(cosAir * cosAir, Number(0.0), Number(1.0))) / (WATER_INDEX * WATER_INDEX);
  return sqrt(1.0 - s);
}

// Light reaching a point of the floor `depthM` below the surface, per unit area of the horizontal
// floor: the Sun's transmitted beam (`sunBelowSurface` = its irradiance on a horizontal surface
// just below the water, Fresnel loss included) along its refracted path depthM / cosSunWater,
// times `sunFactor` (caustics x shadows x the facet's tilt, 1 on a flat open floor), plus the
// diffuse sky light `skyBelowSurface` attenuated by K over the vertical (K is the diffuse
// attenuation coefficient, defined for that path: Jerlov 1976).
vec3 floorIrradiance(vec3 attenuationPerM, Number depthM, Number cosSunWater, vec3 sunBelowSurface,
                     Number sunFactor, vec3 skyBelowSurface) {
  vec3 sun = sunBelowSurface * sunFactor *
             waterTransmittance(attenuationPerM, depthM / max(cosSunWater, Number(0.05)));
  return sun + skyBelowSurface * waterTransmittance(attenuationPerM, depthM);
}

// Radiance leaving the sea surface (above it, before the Fresnel factor the caller applies) from
// a water column: a Lambertian floor of albedo `floorAlbedo` lit by `floorIrr` (floorIrradiance)
// seen along `viewPathM` metres of water, plus the water's own in-scattering, which is the deep
// sea's radiance `deepReflectance` x `surfaceIrradiance` (above-surface irradiance on the
// horizontal) over all but the light the path down and up lets through (Eq. 1 of Baboud &
// Decoret 2006 with L_d the deep water's radiance; seen vertically with the Sun overhead,
// R(H) = R_inf + (A - R_inf) exp(-2 K H), Maritorena et al. 1994 Eq. 9).
vec3 waterColumnRadiance(vec3 attenuationPerM, vec3 deepReflectance, vec3 floorAlbedo, vec3 floorIrr,
                         Number depthM, Number viewPathM, vec3 surfaceIrradiance) {
  vec3 floorSeen = WATER_LEAVING_FACTOR * floorAlbedo / PI * floorIrr *
                   waterTransmittance(attenuationPerM, viewPathM);
  vec3 column = deepReflectance * surfaceIrradiance *
                (1.0 - waterTransmittance(attenuationPerM, depthM + viewPathM));
  return floorSeen + column;
}

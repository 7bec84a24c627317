// The outputs every pass of the HDR target writes (render/GlobeRenderer):
//   location 0: radiance (rgb, units of the Sun's irradiance) and coverage (alpha);
//   location 1: auxiliary channels, attached only when an EXR asks for them (--aov), else
//               dropped: r = whitecap coverage of the pixel, [0, 1].
layout(location = 0) out vec4 fragRadiance;
layout(location = 1) out vec4 fragAux;

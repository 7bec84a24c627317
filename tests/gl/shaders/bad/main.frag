#version 450 core
// Test fixture: the error sits in an included file, which messages must name.
#include "bad/inner.glsl"
out vec4 c;
void main() { c = vec4(inner()); }

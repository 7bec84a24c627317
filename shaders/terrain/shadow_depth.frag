#version 450 core
// The Sun's shadow map: depth only (terrain.vert with the light's matrix).
void main() {}

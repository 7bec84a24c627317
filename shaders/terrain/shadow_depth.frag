#version 450 core
// The Sun's shadow map: depth only (terrain.vert with the light's matrix, TERRAIN_SHADOW_CASTER).
// Ground below sea level casts no shadow: it lies under the water surface, which it must not
// shade; the vertex shader's clip distance leaves it out (a discard here made every fragment
// of the maps run this shader, 2048 x 2048 of them per cascade).
void main() {}

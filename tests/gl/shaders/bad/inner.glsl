// Test fixture for shader error reporting.
float inner() {
  return undefined_symbol_here;
}

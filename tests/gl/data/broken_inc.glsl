// A header with an error on line 4.
vec3 helper() {
  vec3 a = vec3(1.0);
  return a + undefined_symbol;
}

// A fixture for scripts/check_registries.sh: a reactive method special-cased by its name.
double line_width(const deepguide::ReactiveMethod& method) {
  return method == deepguide::ReactiveMethod::dipole ? 2 : 1;
}

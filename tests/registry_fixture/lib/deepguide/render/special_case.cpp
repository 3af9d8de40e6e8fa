// A fixture for scripts/check_registries.sh: a graph special-cased by its kind.
bool draws_cells(const deepguide::PlannerOptions& options) { return options.graph == deepguide::GraphKind::quadtree; }

"""Domain knowledge: the asset catalog, predicates and the action library."""

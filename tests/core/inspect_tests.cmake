# Interior inspection: clip sets, CSG expressions, and the capping / CSG / highlight
# decisions of the walk and the CPU reference.
trimlab_add_test(core clip_set LIBS trimlab::core)
trimlab_add_test(core csg_expression LIBS trimlab::core)
trimlab_add_test(core inspect_walk LIBS trimlab::core)
trimlab_add_test(core inspect_reference LIBS trimlab::core)
# Transparency / X-ray: the compositing of the walk's layers and the reference's identities.
trimlab_add_test(core transparency LIBS trimlab::core)

# scene/: the user-edited object transform (the Scene panel's numeric entry).
trimlab_add_test(core object_transform LIBS trimlab::core)

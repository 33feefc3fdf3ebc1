# Mesh animations and their segmentation (core/animation/; thesis chapter 3).
target_sources(trimlab_core PRIVATE
  animation/animation_loader.cpp
  animation/animation_segmenter.cpp
  animation/color_wheel.cpp
  animation/deformation_gradient.cpp
  animation/face_labels.cpp
  animation/gltf_animated_geometry.cpp
  animation/gltf_animation.cpp
  animation/gltf_animation_clip.cpp
  animation/gltf_keyframes.cpp
  animation/gltf_node_transforms.cpp
  animation/hierarchical_partition.cpp
  animation/label_adjacency.cpp
  animation/mesh_animation.cpp
  animation/natural_order.cpp
  animation/over_segmentation.cpp
  animation/p2p_cleaning.cpp
  animation/parallel_for.cpp
  animation/pose_features.cpp
  animation/pose_join.cpp
  animation/pose_partition.cpp
  animation/pose_topology.cpp
  animation/pose_welding.cpp
  animation/region_growing_partition.cpp
  animation/seeded_region_growing.cpp
  animation/segment_coloring.cpp
  animation/segmentation_combination.cpp
  animation/segmentation_export.cpp
  animation/segmentation_gltf.cpp
  animation/segmentation_record.cpp
  animation/sequence_files.cpp
  animation/sequence_loader.cpp
  animation/task_control.cpp
  animation/vertex_areas.cpp
  animation/vertex_graph.cpp
)

# Skinning of mesh animations (core/animation/skinning_*; thesis 2.3 and chapter 4).
target_sources(trimlab_core PRIVATE
  animation/dual_quaternion.cpp
  animation/nnls.cpp
  animation/skinning_corrections.cpp
  animation/skinning_dqs_fit.cpp
  animation/skinning_error.cpp
  animation/skinning_fitter.cpp
  animation/skinning_lbs_fit.cpp
  animation/skinning_model.cpp
  animation/skinning_normal_equations.cpp
  animation/skinning_pose_fit.cpp
  animation/skinning_propagation.cpp
  animation/skinning_reconstruction.cpp
  animation/skinning_weights.cpp
)

# Exporting skinned animations as glTF, and segmentations with a given segment (bone) count.
target_sources(trimlab_core PRIVATE
  animation/segment_count_search.cpp
  animation/skinning_gltf.cpp
  animation/skinning_gltf_joints.cpp
  animation/skinning_gltf_morph.cpp
  animation/skinning_gltf_skin.cpp
  animation/skinning_rigid_joint_solver.cpp
)

# render/mfr: the multi-fragment methods behind one interface (fragment_method.h).
target_sources(trimlab_render PRIVATE
  mfr/fragment_method.cpp
  mfr/trim_frame.cpp
  mfr/method_factory.cpp
  mfr/pixel_state.cpp
  mfr/slot_array.cpp
  mfr/kplus_buffer.cpp
  # buffer methods (S-buffer, K+B-SB, AB_FP, AB_LL)
  mfr/node_buffer.cpp
  mfr/head_image.cpp
  mfr/memory_referencing.cpp
  mfr/resolve_budget.cpp
  mfr/s_buffer.cpp
  mfr/kplus_s_buffer.cpp
  mfr/abuffer_fixed.cpp
  mfr/abuffer_linked_list.cpp
  # peeling methods (F2B, DUAL, two-pass)
  mfr/peeling_state.cpp
  mfr/peeling_passes.cpp
  mfr/f2b_peeling.cpp
  mfr/dual_peeling.cpp
  mfr/two_pass.cpp
)

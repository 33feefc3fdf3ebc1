# render/mfr: the multi-fragment methods behind one interface (fragment_method.h).
target_sources(trimlab_render PRIVATE
  mfr/fragment_method.cpp
  mfr/method_factory.cpp
  mfr/pixel_state.cpp
  mfr/kplus_buffer.cpp
  # buffer methods (S-buffer, K+B-SB, AB_FP, AB_LL)
  # peeling methods (F2B, DUAL, two-pass)
)

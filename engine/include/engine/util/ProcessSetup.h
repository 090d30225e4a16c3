#pragma once

namespace engine {

// Keeps glibc from handing the heap top back to the kernel after every frame: llvmpipe
// then re-faults its per-frame buffers, 15-20 ms per frame on a 110k-triangle scene
// (356k vs 37k page faults, measured on Mesa llvmpipe 22.3). Call once at program start.
void tuneAllocatorForRendering();

} // namespace engine

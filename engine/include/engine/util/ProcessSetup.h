#pragma once

namespace engine {

// Keeps glibc from handing the heap top back to the kernel after every frame: llvmpipe
// then re-faults its per-frame buffers, 15-20 ms per frame on a 110k-triangle scene
// (DESIGN.md, measured on llvmpipe). Call once at program start.
void tuneAllocatorForRendering();

} // namespace engine

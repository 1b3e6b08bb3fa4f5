/* jemalloc without page decay: LibTorch's large activations are reused instead of refaulted (deps.md §5). */
const char* malloc_conf = "dirty_decay_ms:-1,muzzy_decay_ms:-1";

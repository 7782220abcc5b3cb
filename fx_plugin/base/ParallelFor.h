#pragma once
// The host's job system (HostAdapter::parallelFor) as the plugin's CPU work uses it: a loop over
// n items split into pieces, each piece a task. The pieces are fixed by n alone (splitWork), never
// by the host's thread count, so a result combined piece by piece (a sum, a histogram) is the same
// bit for bit on one thread or sixty-four. Without a host, or for one piece, the pieces run in
// order on the calling thread with no call into the host.
#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <thread>
#include <type_traits>

#include "fx/HostAdapter.h"

namespace fx {

/// [0, n) in `count` pieces of nearly equal size: piece i is [begin(i), end(i)).
struct Pieces {
    uint32_t count = 1;
    size_t n = 0;
    size_t begin(uint32_t i) const { return n * i / count; }
    size_t end(uint32_t i) const { return n * (i + 1) / count; }
};

/// Pieces of at least `grain` items, at most `maxPieces` (and HostAdapter::kMaxTasks): one piece
/// below 2 * grain, where handing work to other threads costs more than it saves.
inline Pieces splitWork(size_t n, size_t grain, uint32_t maxPieces) {
    const size_t cap = std::min<size_t>(std::max<uint32_t>(maxPieces, 1u), HostAdapter::kMaxTasks);
    const size_t count = grain > 0 ? std::min(cap, std::max<size_t>(n / grain, 1)) : 1;
    return Pieces{uint32_t(count), n};
}

class Jobs {
public:
    Jobs() = default;
    /// `host` null: every piece on the calling thread.
    explicit Jobs(HostAdapter* host) : host_(host) {}

    /// Whether there is a host to hand pieces to (else run() is a plain loop).
    bool parallel() const { return host_ != nullptr; }

    /// f(i) for every piece i of `pieces`, each exactly once; returns when all have returned. f
    /// must not depend on the order the pieces run in. Each piece runs once whatever the host
    /// does: a second call for a piece returns at once, and a piece the host's job system did not
    /// run is run here after it returns, so a careless host costs time, not results.
    template <class F>
    void run(const Pieces& pieces, F&& f) const {
        if (!host_ || pieces.count <= 1 || pieces.count > HostAdapter::kMaxTasks) {
            for (uint32_t i = 0; i < pieces.count; ++i) f(i);
            return;
        }
        using Fn = std::remove_reference_t<F>;
        struct Call {
            Fn* fn;
            uint32_t count;
            std::array<std::atomic<uint8_t>, HostAdapter::kMaxTasks> started, done;
        } call{&f, pieces.count, {}, {}};
        for (uint32_t i = 0; i < call.count; ++i) {
            call.started[i].store(0, std::memory_order_relaxed);
            call.done[i].store(0, std::memory_order_relaxed);
        }
        host_->parallelFor(
            call.count,
            [](void* data, uint32_t i) {
                Call& c = *static_cast<Call*>(data);
                if (i >= c.count || c.started[i].exchange(1, std::memory_order_acq_rel)) return;
                (*c.fn)(i);
                c.done[i].store(1, std::memory_order_release);
            },
            &call);
        for (uint32_t i = 0; i < call.count; ++i) {
            if (!call.started[i].exchange(1, std::memory_order_acq_rel)) {
                f(i);  // dropped by the host
            } else {
                // Started by the host: finished, unless its job system returned early.
                while (!call.done[i].load(std::memory_order_acquire)) std::this_thread::yield();
            }
        }
    }

private:
    HostAdapter* host_ = nullptr;
};

}  // namespace fx

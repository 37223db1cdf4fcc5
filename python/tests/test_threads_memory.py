"""The GIL is released while the physics runs (another Python thread keeps running during a long
sweep), and memory stays flat over repeated 1e6-point sweeps (nothing a sweep allocates
outlives its result)."""

from __future__ import annotations

import gc
import sys
import threading
import time

import numpy as np
import pytest

import microslip


def test_a_long_sweep_lets_other_threads_run():
    beams = microslip.preset("paper-beams")
    forces = np.linspace(0.0, 240.0, 2_000_000)
    done = threading.Event()
    took = {}

    def work():
        start = time.perf_counter()
        beams.sweep(F=forces, quantities=["X", "ratio"])
        took["sweep"] = time.perf_counter() - start
        done.set()

    worker = threading.Thread(target=work)
    # The longest stretch the main thread could not run while the sweep ran: with the GIL held
    # for the whole sweep it is about the sweep's duration; released, a few switch intervals.
    longest, ticks = 0.0, 0
    worker.start()
    last = time.perf_counter()
    while not done.is_set():
        now = time.perf_counter()
        longest = max(longest, now - last)
        last = now
        ticks += 1
    worker.join()
    # The last stretch too: a sweep holding the GIL would also hold it through `done.set()`.
    longest = max(longest, time.perf_counter() - last)
    assert took["sweep"] > 0.3, "the sweep must be long enough to tell"
    assert longest < took["sweep"] / 4, (longest, took["sweep"], ticks)


def _rss_bytes() -> int:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc/self/statm")
def test_memory_is_flat_over_repeated_million_point_sweeps():
    beams = microslip.preset("paper-beams")
    forces = np.linspace(0.0, 240.0, 1_000_000)
    sizes = []
    # Warm-up rounds: the allocator keeps freed memory in its arenas (one per thread that
    # solved), so RSS may stay up by about one sweep after the first few; it must not grow after.
    for _ in range(3):
        out = beams.sweep(F=forces)
        sizes.append(sum(a.nbytes for a in out.values() if hasattr(a, "nbytes")))
        del out
        gc.collect()
    before = _rss_bytes()
    rounds = 8
    for _ in range(rounds):
        out = beams.sweep(F=forces)
        del out
        gc.collect()
    grown = _rss_bytes() - before
    # A leak of one sweep's arrays (about 42 MB) would add `rounds` times that.
    assert grown < sizes[0], (grown, sizes[0])


def test_a_rust_panic_is_a_runtime_error_not_an_abort():
    """A panic in the physics (simulated: the module has no known one) must not abort Python nor
    escape `except Exception` as PyO3's BaseException-derived PanicException would."""
    from microslip import _native

    with pytest.raises(RuntimeError, match="internal error .*deliberate panic"):
        _native._panic_check()
    assert microslip.preset("paper-beams").solve().regularized.response > 0  # still alive

#!/usr/bin/env python3
"""Start-up to first frame of the TUI in a 120x40 pseudo-terminal: python3 benches/startup_time.py target/release/microslip"""
import os, pty, time, select, sys, statistics
binary = sys.argv[1]
times = []
for _ in range(20):
    pid, fd = pty.fork()
    if pid == 0:
        import fcntl, termios, struct
        fcntl.ioctl(0, termios.TIOCSWINSZ, struct.pack("HHHH", 40, 120, 0, 0))
        os.environ["TERM"] = "xterm-256color"
        os.execv(binary, [binary])
    start = time.perf_counter()
    seen = b""
    while b"Twin beams" not in seen:
        r, _, _ = select.select([fd], [], [], 5)
        if not r: break
        seen += os.read(fd, 65536)
    times.append(time.perf_counter() - start)
    os.write(fd, b"q")
    os.waitpid(pid, 0)
    os.close(fd)
print(f"start-up to first frame: median {statistics.median(times)*1000:.1f} ms, min {min(times)*1000:.1f} ms, max {max(times)*1000:.1f} ms over {len(times)} runs")

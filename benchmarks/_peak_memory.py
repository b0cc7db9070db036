"""The peak memory of the running process, for the benchmarks' child processes."""
import resource


def peak_mb() -> float:
    """The peak resident memory of this process since it started, in MB (VmHWM: unlike
    ru_maxrss, it does not count what the parent held before the exec)."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024

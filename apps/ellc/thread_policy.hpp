#pragma once
// OpenMP threads that spin at barriers (libgomp's default) lose their time slices to each other
// when the machine is busier than its cores, and a 2-thread run then takes ~10x longer than a
// 1-thread one. libgomp reads its wait policy once, before main(), so the commands whose loops are
// OpenMP (`ellc dem`, `ellc analyse`) re-execute themselves once with GOMP_SPINCOUNT=1000 unless
// the user set a policy (docs/engine.md, "Threads"). Both also keep to a CPU quota.

namespace ellc::cli {

// Re-executes this process with GOMP_SPINCOUNT=1000 unless OMP_WAIT_POLICY or GOMP_SPINCOUNT is
// set; returns (and runs as it is) when it cannot.
void prefer_short_spinning();

// Under a CPU quota (a container's --cpus, a Kubernetes limit) libgomp still starts a thread per
// core of the affinity mask; threads beyond the quota only wait, throttled. Caps OpenMP's threads
// at the quota rounded up (engine/cpu_load.hpp), unless OMP_NUM_THREADS says otherwise. Call it
// where the user gave no thread count.
void cap_threads_at_cpu_quota();

}  // namespace ellc::cli

#pragma once
// OpenMP threads that spin at barriers (libgomp's default) lose their time slices to each other
// when the machine is busier than its cores, and a 2-thread run then takes ~10x longer than a
// 1-thread one. libgomp reads its wait policy once, before main(), so the commands whose loops are
// OpenMP (`ellc dem`, `ellc analyse`) re-execute themselves once with GOMP_SPINCOUNT=1000 unless
// the user set a policy (docs/engine.md, "Threads").

namespace ellc::cli {

// Re-executes this process with GOMP_SPINCOUNT=1000 unless OMP_WAIT_POLICY or GOMP_SPINCOUNT is
// set; returns (and runs as it is) when it cannot.
void prefer_short_spinning();

}  // namespace ellc::cli

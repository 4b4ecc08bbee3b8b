# benchmarks targets: see CMakeLists.txt

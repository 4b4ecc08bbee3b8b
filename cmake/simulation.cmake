# simulation targets: see CMakeLists.txt

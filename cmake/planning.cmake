# planning targets: see CMakeLists.txt

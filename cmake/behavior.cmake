# behavior targets: see CMakeLists.txt

# The robot itself: its state (pose, velocity, bumper) and its unicycle model. ROS-free, below the
# simulator (which moves the robot with the model) and navigation (which predicts its pose).

add_library(roomba_robot src/robot/unicycle.cpp)
target_include_directories(roomba_robot PUBLIC ${PROJECT_SOURCE_DIR}/include)

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(robot_test test/robot/unicycle_test.cpp LINK roomba_robot)
endif()

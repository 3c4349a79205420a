// behaviorControllerApplication.cpp: the start of a node written as the robot's
// behaviorController is (package cssr_system): the environment knowledge base is a global
// object, constructed before main, and nothing catches what its constructor throws. It
// logs the tour, each stop with its English messages, and needs no roscore.
//
// A refused file ends it before main with the findings, errors first, one fatal line that
// names the file, `ekb check` and `ekb fix`, and exit status 1.
#include <ros/ros.h>

#include "behaviorController/environmentKnowledgeBaseInterface.h"

Environment::EnvironmentKnowledgeBase environmentKnowledgeBase;

int main(int argc, char **argv) {
    ros::init(argc, argv, "behaviorController", ros::init_options::NoRosout);
    Environment::TourSpecificationType tour;
    if (!environmentKnowledgeBase.getTour(&tour)) {
        ROS_ERROR("behaviorController: the environment knowledge base has no tour");
        return 1;
    }
    ROS_INFO("behaviorController: the tour has %d stops", tour.numberOfLocations);
    for (int stop = 0; stop < tour.numberOfLocations; ++stop) {
        Environment::KeyValueType location;
        if (!environmentKnowledgeBase.getValue(tour.locationIdNumber[stop], &location)) {
            ROS_ERROR("behaviorController: stop %d: no location %d", stop + 1, tour.locationIdNumber[stop]);
            return 1;
        }
        ROS_INFO("behaviorController: stop %d: location %d, %s, at (%g, %g, %g): \"%s\" ... \"%s\"", stop + 1,
                 location.key, location.robotLocationDescription, location.robotLocation.x, location.robotLocation.y,
                 location.robotLocation.theta, location.preGestureMessageEnglish, location.postGestureMessageEnglish);
    }
    return 0;
}

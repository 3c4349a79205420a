// tour_node: loads the environment knowledge base as the robot's behaviorController does,
// through the document's class (here ekb's drop-in), and logs the tour with its English
// messages. It needs no roscore: it only logs.
//
// A file with an error is refused: the node catches the ekb::LoadError, logs its findings
// as the class does when nothing catches it (errors first, then a fatal line naming the
// file), and exits 1. (A node that catches nothing ends the same way: see
// crates/ekb-capi/tests/cssr_system.)
#include <ros/ros.h>

#include "environmentKnowledgeBaseInterface.h"

int main(int argc, char **argv) {
    ros::init(argc, argv, "ekb_tour_example", ros::init_options::NoRosout);
    try {
        Environment::EnvironmentKnowledgeBase knowledgeBase;
        Environment::TourSpecificationType tour;
        if (!knowledgeBase.getTour(&tour)) {
            ROS_ERROR("the knowledge base has no tour");
            return 1;
        }
        ROS_INFO("The tour has %d stops", tour.numberOfLocations);
        for (int stop = 0; stop < tour.numberOfLocations; ++stop) {
            Environment::KeyValueType location;
            if (!knowledgeBase.getValue(tour.locationIdNumber[stop], &location)) {
                ROS_ERROR("stop %d: no location %d", stop + 1, tour.locationIdNumber[stop]);
                return 1;
            }
            ROS_INFO("Stop %d: location %d, %s, at (%g, %g, %g): \"%s\" ... \"%s\"", stop + 1, location.key,
                     location.robotLocationDescription, location.robotLocation.x, location.robotLocation.y,
                     location.robotLocation.theta, location.preGestureMessageEnglish,
                     location.postGestureMessageEnglish);
        }
    } catch (const ekb::LoadError &error) {
        Environment::EnvironmentKnowledgeBase::report(error);
        return 1;
    }
    return 0;
}

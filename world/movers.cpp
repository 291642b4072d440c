#include "world/movers.hpp"

namespace onelight::world {

std::vector<MoverPose> moverReach(const LevelMovers& movers, const Mover& mover) {
    std::vector<MoverPose> poses;
    switch (mover.kind) {
        case MoverKind::kShuttle:
        case MoverKind::kDoor:
        case MoverKind::kPlat:
        case MoverKind::kButton:
            poses.push_back({mover.pos1});
            poses.push_back({mover.pos2});
            break;
        case MoverKind::kBobbing:
            poses.push_back({mover.pos1 - mover.amplitude});
            poses.push_back({mover.pos1 + mover.amplitude});
            break;
        case MoverKind::kRotating:
            for (int k = 0; k < 8; ++k)
                poses.push_back({mover.pos1, glm::angleAxis(float(k) * 0.785398163f, mover.axis)});
            break;
        case MoverKind::kPendulum:
            for (float s : {-1.0f, -0.5f, 0.0f, 0.5f, 1.0f})
                poses.push_back({mover.pos1, glm::angleAxis(s * mover.speed, mover.axis)});
            break;
        case MoverKind::kTrain:
            for (uint32_t p = mover.firstPoint;
                 p < mover.firstPoint + mover.pointCount && p < movers.path.size(); ++p)
                poses.push_back({movers.path[p].position});
            break;
    }
    return poses;
}

}  // namespace onelight::world

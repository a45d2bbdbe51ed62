// The public members of every exported class, as the published declarations hold them (checked
// against the declarations by public-types-expose-no-internal-state.test.ts); the bad-input audit
// (bad-input-everywhere.test.ts) drives every one of them.

/** Each class's public member names, space-separated. */
export const PUBLIC_MEMBERS: Record<string, string> = {
  Body:
    'type userData constructor world position angle centerOfMass linearVelocity angularVelocity ' +
    'kineticEnergy getWorldPoint getLocalPoint getVelocityAt mass inertia resetMass ' +
    'localCenterOfMass gravityScale linearDamping angularDamping drag fixedRotation bullet ' +
    'allowSleep isAwake wake sleep shapes addShape removeShape joints forces applyForce ' +
    'applyTorque removeForce clearForces applyImpulse applyAngularImpulse on off',
  Shape:
    'body geometry density sensor constructor friction restitution filter collidesWith getBounds',
  Force: 'duration constructor x y torque remaining setVector setTorque remove isExpired',
  World:
    'constructor gravity subSteps restitutionThreshold enableSleep bodies steps isStepping add ' +
    'remove has clear joints addJoint removeJoint step bodyAt bodiesInAABB rayCast rayCastAll ' +
    'shapeCast overlapShape awakeBodyCount forEachContact on off',
  Joint:
    'type bodyA bodyB collideConnected userData constructor world reactionForce reactionTorque ' +
    'anchorA anchorB',
  DistanceJoint:
    'type constructor currentLength length minLength maxLength setLengthRange enableSpring hertz ' +
    'dampingRatio',
  MouseJoint: 'type constructor body target maxForce hertz dampingRatio',
  PrismaticJoint:
    'type constructor translation enableLimit lower upper setLimits enableMotor motorSpeed ' +
    'maxMotorForce motorForce enableSpring hertz dampingRatio',
  RevoluteJoint:
    'type constructor angle angularSpeed enableLimit lowerAngle upperAngle setLimits enableMotor ' +
    'motorSpeed maxMotorTorque motorTorque enableSpring hertz dampingRatio',
  WeldJoint: 'type constructor linearHertz angularHertz dampingRatio',
  PhysicalError: 'field constructor',
  // Body's base: the accessors of its numbers in the body memory, every one internal.
  BodyNumbers: '',
  // The base of the two-body joints (two-body-joint.ts): setters and the frame, every one internal.
  TwoBodyJoint: '',
};

Vec3 FP0 = new Vec3();
FP0.barycenter(<0,1>_pos(n0));
Vec3 FP1 = new Vec3();
FP1.barycenter(<0,1>_pos(n0@2));
return (((n0.pos.addn(n0@0.pos)).mul(0.5)).addn(FP0).addn(FP1)).div(3.0);
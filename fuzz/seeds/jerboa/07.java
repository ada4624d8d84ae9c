Vec3 res = new Vec3();
res.barycenter(<0,1>_pos(n0));
return new Vec3(Vec3.segmentABByWeight(n0.pos, res, 0.5f));
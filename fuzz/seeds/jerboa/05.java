Vec3 center = new Vec3();
center.barycenter(<0,1,3>_pos(n0));
return new Vec3(Vec3.segmentABByWeight(n0.pos, center, 0.4f));
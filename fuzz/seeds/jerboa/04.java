Vec3 bary = new Vec3();
bary.barycenter(<0,1>_pos(n0));
return bary;
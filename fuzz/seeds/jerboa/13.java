Vec3 res = new Vec3();
res.barycenter(<0>_pos(n0));
return res;
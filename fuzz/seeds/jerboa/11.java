Vec3 res = new Vec3();
res.barycenter(<0,2,3>_pos(n0));
return res;
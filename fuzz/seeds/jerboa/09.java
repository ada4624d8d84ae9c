Vec3 res = new Vec3();
res.barycenter(<0,1>_pos(n0));
return res.addn(0,0,1);
Vec3 res = new Vec3();
res.barycenter(<0,1>_pos(n0));
return new Vec3(res).addn(0.0f,height,0.0f);
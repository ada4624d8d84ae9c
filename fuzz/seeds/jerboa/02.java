JerboaList<Vec3> faceList;
for(JerboaDart face : <1,2>(n0)){
    Vec3 a = new Vec3();
    a.barycenter(<0,1>_pos(face));
    faceList.add(a);
}

Vec3 F = new Vec3();
F.barycenter(faceList);
JerboaDarts edgeList = <1,2>_<2>(n0);
int k = edgeList.size();
Vec3 R = new Vec3();
for( JerboaDart edge : edgeList){
    R = R.addn((edge@0.pos.addn(edge.pos)).div(2.0));
}
R = R.div(k);
return (R.mul(2).addn(F).addn(n0.pos.mul(k-3))).div(k);
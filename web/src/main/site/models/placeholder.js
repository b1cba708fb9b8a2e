// The figure that stands in for an agent whose model cannot be shown, or that sent none: its
// body's size in the agent's colour, its nose showing its heading.
import * as THREE from '../vendor/three/build/three.module.js';
import { SpatialRig } from './rigs.js';

export function placeholder(agent, colour) {
    const group = new THREE.Group();
    group.name = 'placeholder';
    const paint = new THREE.MeshLambertMaterial({ color: colour });
    const { radius, height } = agent.body;
    const torso = new THREE.Mesh(new THREE.CylinderGeometry(radius * 0.8, radius, height * 0.75, 16), paint);
    torso.position.y = height * 0.375;
    const head = new THREE.Mesh(new THREE.SphereGeometry(radius * 0.7, 16, 12), paint);
    head.position.y = height * 0.75 + radius * 0.5;
    const nose = new THREE.Mesh(new THREE.ConeGeometry(radius * 0.25, radius * 0.8, 8),
        new THREE.MeshLambertMaterial({ color: 0x222222 }));
    // The model's front is -z, north, as heading 0 faces.
    nose.rotation.x = -Math.PI / 2;
    nose.position.set(0, head.position.y, -radius * 0.9);
    group.add(torso, head, nose);
    return { object: group, rig: new SpatialRig(agent.name, group), placeholder: true };
}

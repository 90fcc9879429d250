export default {id: 'tides', title: 'tides', mount(main) { main.textContent = 'tides'; }};
